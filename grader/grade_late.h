/* grade_late.h: late work: its policy read (grading.conf, --due, --late-until), what it costs a submission. */
#ifndef RAYTRA_GRADE_LATE_H
#define RAYTRA_GRADE_LATE_H

#include <stdbool.h>

#include "grading.h"

/* What lateness costs one submission. */
typedef struct {
    bool known;     /* a due date is set and the submission's time is known */
    double after;   /* seconds from the due date to the time it was handed in (< 0: before) */
    int days;       /* days late, rounded up, counted from the end of the grace; 0: on time */
    bool zero;      /* later than max_late_days or late_until allow: the work gets 0 */
    double penalty; /* the percent of its points it loses */
    double points, max, final; /* its points before the penalty, the most, and after */
} Lateness;

bool late_conf_line(Grading *g, char **words, int n, const char *where, unsigned *seen, bool *ok);
bool late_read_options(Grading *g);
Lateness late_of(const Grading *g, const Submission *s);
const char *late_source_text(const char *source);
char *late_describe(const Grading *g, const Submission *s);

#endif
