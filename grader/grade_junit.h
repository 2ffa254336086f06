/* grade_junit.h: the verdicts as JUnit XML. */
#ifndef RAYTRA_GRADE_JUNIT_H
#define RAYTRA_GRADE_JUNIT_H

#include <stdbool.h>

#include "grading.h"

bool junit_export(const Grading *g, const char *path);

#endif
