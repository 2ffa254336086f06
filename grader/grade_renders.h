/* grade_renders.h: renders.txt read into the renders a grading judges. */
#ifndef RAYTRA_GRADE_RENDERS_H
#define RAYTRA_GRADE_RENDERS_H

#include <stdbool.h>

#include "grading.h"

bool renders_read(Grading *g);
bool renders_read_hidden(Grading *g);

#endif
