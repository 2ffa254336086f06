/* grade_eta.c: a class's progress in time: k of N submissions done, the time elapsed, an ETA. */
#include "grade_eta.h"

#include <math.h>

#include "grade_base.h"
#include "progress.h"

/* Starts the count of `total` submissions, graded `jobs` at a time, from now. */
void eta_start(Eta *e, int total, int jobs)
{
    *e = (Eta){.total = total, .jobs = jobs > 1 ? jobs : 1, .began = clock_now()};
}

/* Returns a duration in words, to the second: "41 s", "5 min 20 s", "1 h 5 min". */
char *eta_format_duration(double seconds)
{
    long s = seconds > 0 ? lround(seconds) : 0;
    return s < 60     ? grade_format("%ld s", s)
           : s < 3600 ? grade_format("%ld min %ld s", s / 60, s % 60)
                      : grade_format("%ld h %ld min", s / 3600, s / 60 % 60);
}

/* Counts a submission done, which took `seconds`, and returns the end of the line that
 * tells it: " [k of N done, E elapsed, ETA T]". The ETA is the mean time of a finished
 * submission for each one left, less what those still running (begun at the clock_now
 * times `running`, `count` of them) have done, shared among the jobs that will run them;
 * there is none after the last. */
char *eta_done(Eta *e, double seconds, const double *running, int count)
{
    double now = clock_now();
    e->done++;
    e->spent += seconds;
    char *said = grade_format(" [%d of %d done, %s elapsed", e->done, e->total,
                              eta_format_duration(now - e->began));
    int left = e->total - e->done;
    if (left <= 0)
        return grade_format("%s]", said);
    double mean = e->spent / e->done, work = mean * left;
    for (int k = 0; k < count; k++)
        work -= fmin(now - running[k], mean);
    int jobs = e->jobs < left ? e->jobs : left;
    return grade_format("%s, ETA %s]", said, eta_format_duration(fmax(work, 0) / jobs));
}
