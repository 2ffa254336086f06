/* progress.c: a bar like "42% [#####     ] 1.3 s, about 1.8 s left", redrawn five times a second. */
#include "progress.h"

#include <stdio.h>
#include <time.h>

/* How often the bar is redrawn, in seconds. */
#define PROGRESS_INTERVAL 0.2
#define PROGRESS_WIDTH 30

/* Returns a monotonic time in seconds. */
double clock_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Starts a bar that reaches 100% at total units of work. */
void progress_start(Progress *pr, long total, bool enabled)
{
    pr->enabled = enabled && total > 0;
    pr->total = total;
    pr->start = pr->last_draw = clock_now();
    pr->drawn = false;
    pthread_mutex_init(&pr->lock, NULL);
}

/* Redraws the bar for done units, unless it was drawn very recently or another
 * thread is drawing it; safe to call from any thread. */
void progress_update(Progress *pr, long done)
{
    if (!pr->enabled || pthread_mutex_trylock(&pr->lock) != 0)
        return;
    double now = clock_now();
    if (now - pr->last_draw >= PROGRESS_INTERVAL) {
        double fraction = (double)done / (double)pr->total;
        double elapsed = now - pr->start;
        int filled = (int)(fraction * PROGRESS_WIDTH);
        char bar[PROGRESS_WIDTH + 1];
        for (int k = 0; k < PROGRESS_WIDTH; k++)
            bar[k] = k < filled ? '#' : ' ';
        bar[PROGRESS_WIDTH] = '\0';
        fprintf(stderr, "\r%4.0f%% [%s] %.1f s", 100 * fraction, bar, elapsed);
        /* The time left, assuming the rest goes as fast as what is done. */
        if (fraction > 0.02)
            fprintf(stderr, ", about %.0f s left ", elapsed * (1 - fraction) / fraction);
        fflush(stderr);
        pr->last_draw = now;
        pr->drawn = true;
    }
    pthread_mutex_unlock(&pr->lock);
}

/* Clears the bar's line so that the summary can take its place. */
void progress_finish(Progress *pr)
{
    if (pr->drawn)
        fprintf(stderr, "\r%*s\r", PROGRESS_WIDTH + 40, "");
    pthread_mutex_destroy(&pr->lock);
}
