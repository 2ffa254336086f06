/* grade_jobs.h: the submissions graded N at a time, in workers. */
#ifndef RAYTRA_GRADE_JOBS_H
#define RAYTRA_GRADE_JOBS_H

#include <stdbool.h>

#include "grading.h"

bool jobs_grade_all(Grading *g);

#endif
