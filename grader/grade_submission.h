/* grade_submission.h: the class's submissions listed, and each graded. */
#ifndef RAYTRA_GRADE_SUBMISSION_H
#define RAYTRA_GRADE_SUBMISSION_H

#include <stdbool.h>
#include <stdio.h>

#include "grading.h"

bool submission_list(Grading *g);
bool submission_grade(const Grading *g, Submission *s, FILE *f);

#endif
