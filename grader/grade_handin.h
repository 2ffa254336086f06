/* grade_handin.h: when each submission was handed in. */
#ifndef RAYTRA_GRADE_HANDIN_H
#define RAYTRA_GRADE_HANDIN_H

#include "grading.h"

void handin_find_all(Grading *g);

#endif
