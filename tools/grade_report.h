/* grade_report.h: the grading report, one self-contained HTML page, grades.csv, and --self's. */
#ifndef RAYTRA_GRADE_REPORT_H
#define RAYTRA_GRADE_REPORT_H

#include <stdbool.h>

#include "grade.h"

bool report_write(const Grading *g);
int report_print_self(const Grading *g);

#endif
