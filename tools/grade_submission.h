/* grade_submission.h: grading one submission: its images, or the images its program renders. */
#ifndef RAYTRA_GRADE_SUBMISSION_H
#define RAYTRA_GRADE_SUBMISSION_H

#include <stdbool.h>

#include "grade.h"

bool submission_list(Grading *g);
bool submission_grade_all(Grading *g);

#endif
