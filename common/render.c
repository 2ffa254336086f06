/* render.c: threads take rows from a shared counter and write each pixel to its own slot. */
#include "render.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "progress.h"
#include "stop.h"

/* More threads than this buys nothing on any machine a course uses. */
#define RENDER_MAX_THREADS 256

/* What the threads of one render share. */
typedef struct {
    Image *img;
    const RenderJob *job;
    atomic_int next_row;
    atomic_long rows_done;
    Progress progress;
    pthread_mutex_t lock; /* guards result */
    RenderResult *result;
} Shared;

/* The colour a pixel gets when its own is not a number the image can hold: magenta,
 * which no scene of the course makes by accident, so that the bug shows. */
static const Color nonfinite_marker = {1.0, 0.0, 1.0};

/* Tells whether every component of c is finite and stays finite as the image's float:
 * a double beyond FLT_MAX (3.4e38) is finite but would be stored as infinity. */
static bool fits_image(Color c)
{
    return fabs(c.r) <= FLT_MAX && fabs(c.g) <= FLT_MAX && fabs(c.b) <= FLT_MAX;
}

/* Renders rows until none are left, then adds this thread's counts to the result. */
static void *render_rows(void *arg)
{
    Shared *s = arg;
    const RenderJob *job = s->job;
    Image *img = s->img;
    RayStats stats;
    memset(&stats, 0, sizeof stats);
    long bad = 0;
    int bad_x = -1, bad_y = INT_MAX;
    for (;;) {
        int y = atomic_fetch_add(&s->next_row, 1);
        if (y >= img->height)
            break;
        int j = img->height - 1 - y;
        for (int i = 0; i < img->width && !stop_requested(); i++) {
            Color c = job->pixel(job->ctx, i, j, &stats);
            if (!fits_image(c)) {
                /* Rows come in increasing order, so a thread's first is its smallest. */
                if (bad++ == 0) {
                    bad_x = i;
                    bad_y = y;
                }
                c = nonfinite_marker;
            }
            image_set(img, i, y, c);
        }
        if (stop_requested())
            break;
        progress_update(&s->progress, atomic_fetch_add(&s->rows_done, 1) + 1);
    }
    pthread_mutex_lock(&s->lock);
    RenderResult *r = s->result;
    for (int k = 0; k < RAY_KIND_COUNT; k++)
        r->stats.rays[k] += stats.rays[k];
    r->nonfinite += bad;
    /* The first bad pixel in reading order, whichever thread found it. */
    if (bad > 0 && (bad_y < r->first_nonfinite_y ||
                    (bad_y == r->first_nonfinite_y && bad_x < r->first_nonfinite_x))) {
        r->first_nonfinite_x = bad_x;
        r->first_nonfinite_y = bad_y;
    }
    pthread_mutex_unlock(&s->lock);
    return NULL;
}

/* Fills img by calling job->pixel for every pixel on job->threads threads. As every
 * pixel is computed by itself and stored in its own place, the image is the same
 * whatever the number of threads and whichever thread renders which row. */
void render_image(Image *img, const RenderJob *job, RenderResult *result)
{
    memset(result, 0, sizeof *result);
    result->first_nonfinite_x = INT_MAX;
    result->first_nonfinite_y = INT_MAX;
    Shared s = {.img = img, .job = job, .result = result};
    atomic_init(&s.next_row, 0);
    atomic_init(&s.rows_done, 0);
    pthread_mutex_init(&s.lock, NULL);
    progress_start(&s.progress, img->height, job->progress);
    double start = clock_now();

    int threads = job->threads < 1 ? 1 : job->threads;
    if (threads > RENDER_MAX_THREADS)
        threads = RENDER_MAX_THREADS;
    pthread_t tid[RENDER_MAX_THREADS];
    int started = 0;
    /* This thread is one of the workers; a thread that cannot start is simply not there. */
    while (started < threads - 1 && pthread_create(&tid[started], NULL, render_rows, &s) == 0)
        started++;
    render_rows(&s);
    for (int k = 0; k < started; k++)
        pthread_join(tid[k], NULL);

    result->seconds = clock_now() - start;
    result->stopped = stop_requested();
    progress_finish(&s.progress);
    pthread_mutex_destroy(&s.lock);
}

/* Returns the number of processors online: the default thread count. */
int render_default_threads(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n < 1 ? 1 : n > RENDER_MAX_THREADS ? RENDER_MAX_THREADS : (int)n;
}

/* Returns the number of rays of all kinds. */
unsigned long long render_total_rays(const RayStats *stats)
{
    unsigned long long total = 0;
    for (int k = 0; k < RAY_KIND_COUNT; k++)
        total += stats->rays[k];
    return total;
}

/* Returns the name of a kind of ray, for the summary line. */
const char *render_ray_kind_name(RayKind kind)
{
    static const char *const names[RAY_KIND_COUNT] = {"primary", "shadow", "reflected",
                                                      "refracted"};
    return names[kind];
}
