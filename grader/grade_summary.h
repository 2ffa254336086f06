/* grade_summary.h: the report's summary: a row a submission. */
#ifndef RAYTRA_GRADE_SUMMARY_H
#define RAYTRA_GRADE_SUMMARY_H

#include <stdio.h>

#include "grading.h"

void summary_write(FILE *f, const Grading *g);

#endif
