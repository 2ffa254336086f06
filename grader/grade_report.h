/* grade_report.h: report.html, grades.csv and gradebook.csv, each written whole. */
#ifndef RAYTRA_GRADE_REPORT_H
#define RAYTRA_GRADE_REPORT_H

#include <stdbool.h>
#include <stdio.h>

#include "grading.h"

bool report_write(const Grading *g);
bool report_write_whole(const char *path, const Grading *g, void (*write)(FILE *, const Grading *));

#endif
