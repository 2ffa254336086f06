/* grade_eta.h: a class's progress in time: k of N submissions done, the time elapsed, an ETA. */
#ifndef RAYTRA_GRADE_ETA_H
#define RAYTRA_GRADE_ETA_H

/* The submissions of a grading counted as they finish. */
typedef struct {
    int total, done, jobs; /* jobs: how many are graded at a time */
    double began;          /* when the first began, from clock_now */
    double spent;          /* the seconds the finished ones took, added up */
} Eta;

void eta_start(Eta *e, int total, int jobs);
char *eta_format_duration(double seconds);
char *eta_done(Eta *e, double seconds, const double *running, int count);

#endif
