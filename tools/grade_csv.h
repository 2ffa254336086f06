/* grade_csv.h: grades.csv, a line a submission and scene, safe to open in a spreadsheet. */
#ifndef RAYTRA_GRADE_CSV_H
#define RAYTRA_GRADE_CSV_H

#include <stdio.h>

#include "grade.h"

void csv_write(FILE *f, const Grading *g);

#endif
