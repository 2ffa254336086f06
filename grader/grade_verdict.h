/* grade_verdict.h: what became of a scene: each verdict's name and column; a verdict set with its reason. */
#ifndef RAYTRA_GRADE_VERDICT_H
#define RAYTRA_GRADE_VERDICT_H

#include "diag.h"
#include "grading.h"

/* A verdict's name in the report and the CSV ("WRONG SIZE"), and its column. */
typedef struct {
    const char *name;
    Tally tally;
} VerdictInfo;

extern const VerdictInfo verdict_info[VERDICT_COUNT];

void verdict_set(SceneResult *res, Verdict v, const char *fmt, ...) DIAG_PRINTF(3, 4);

#endif
