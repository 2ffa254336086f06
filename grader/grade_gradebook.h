/* grade_gradebook.h: gradebook.csv: a line a student, for a course's gradebook. */
#ifndef RAYTRA_GRADE_GRADEBOOK_H
#define RAYTRA_GRADE_GRADEBOOK_H

#include <stdio.h>

#include "grading.h"

void gradebook_write(FILE *f, const Grading *g);

#endif
