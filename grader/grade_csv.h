/* grade_csv.h: grades.csv: a line a submission and scene. */
#ifndef RAYTRA_GRADE_CSV_H
#define RAYTRA_GRADE_CSV_H

#include <stdio.h>

#include "grading.h"

char *csv_field(const char *text);
void csv_write(FILE *f, const Grading *g);

#endif
