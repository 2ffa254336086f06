/* grade_self.h: --self's lines for a student checking their own work. */
#ifndef RAYTRA_GRADE_SELF_H
#define RAYTRA_GRADE_SELF_H

#include "grading.h"

int self_print(const Grading *g);

#endif
