/* grade_gradescope.h: Gradescope's results.json for the one submission of --self. */
#ifndef RAYTRA_GRADE_GRADESCOPE_H
#define RAYTRA_GRADE_GRADESCOPE_H

#include <stdbool.h>

#include "grading.h"

bool gradescope_export(const Grading *g, const char *path);

#endif
