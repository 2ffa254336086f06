/* grade_regrade.h: --only: students regraded into a class's earlier grading. */
#ifndef RAYTRA_GRADE_REGRADE_H
#define RAYTRA_GRADE_REGRADE_H

#include <stdbool.h>

#include "grading.h"

bool regrade_parse(const Grading *g);
bool regrade_read(const Grading *g, Grading *earlier);
bool regrade_select(Grading *g, const Grading *earlier);
bool regrade_gather(Grading *g, const Grading *earlier);
bool regrade_finish(const Grading *g);

#endif
