/* grade_feedback.h: a scene's verdict told to a student, for JUnit and Gradescope. */
#ifndef RAYTRA_GRADE_FEEDBACK_H
#define RAYTRA_GRADE_FEEDBACK_H

#include <stdbool.h>

#include "grading.h"

char *feedback_text(const Grading *g, const Submission *s, int k, bool build);

#endif
