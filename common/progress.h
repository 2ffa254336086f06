/* progress.h: a progress bar on stderr for long renders, drawn only on a terminal. */
#ifndef RAYTRA_PROGRESS_H
#define RAYTRA_PROGRESS_H

#include <pthread.h>
#include <stdbool.h>

typedef struct {
    bool enabled;
    long total;
    double start;     /* seconds, from clock_now */
    double last_draw; /* when the bar was last drawn */
    bool drawn;       /* something is on the line and must be cleared */
    pthread_mutex_t lock;
} Progress;

double clock_now(void);
void progress_start(Progress *pr, long total, bool enabled);
void progress_update(Progress *pr, long done);
void progress_finish(Progress *pr);

#endif
