/* render.c: threads take rows from a shared counter and write each pixel to its own slot. */
#include "render.h"

#include <float.h>
#include <limits.h>
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "progress.h"
#include "stop.h"

/* More threads than this buys nothing on any machine a course uses. */
#define RENDER_MAX_THREADS 256

/* The stack of every render thread. A path of the largest --max-depth, 1000, takes less
 * than 2 MiB of it at -O2 (about 1.5 KiB a bounce in parts 1.5 and 1.6), a few times that
 * under the sanitizers; asking for it explicitly makes the depth work whatever
 * `ulimit -s` gives the main thread, which is also the default of other threads. More
 * costs nothing natively but is slow under valgrind, which marks all of it. */
#define RENDER_STACK_SIZE ((size_t)16 << 20)

/* After a stop request, how long the waiting thread lets the workers finish their pixel
 * before it gives them up, and how often it looks at the request meanwhile (seconds). */
#define RENDER_STOP_GRACE 0.5
#define RENDER_POLL_INTERVAL 0.01

/* Threads of a crew still running, in this process: zero once every crew is done. */
static atomic_int threads_alive;

/* A crew: the threads of one render (or one call), and what they share. The waiting
 * thread and each worker own it; the last one to leave frees it, so that workers given
 * up after a stop (see render_image) never touch freed memory. */
typedef struct Crew Crew;
struct Crew {
    pthread_mutex_t lock;    /* guards running, owners and total */
    pthread_cond_t finished; /* signalled when a worker is done */
    int running;             /* workers still working */
    int owners;              /* running workers, and the waiting thread until it leaves */
    void (*work)(Crew *crew);
    /* For render_image: */
    Image *img;
    const RenderJob *job;
    atomic_int next_row;
    atomic_long rows_done;
    Progress progress;
    bool progress_started;
    RenderResult total; /* the workers' counts, added up */
    /* For render_call: */
    void (*fn)(void *arg);
    void *arg;
};

/* The colour a pixel gets when its own is not a number the image can hold: magenta,
 * which no scene of the course makes by accident, so that the bug shows. */
static const Color nonfinite_marker = {1.0, 0.0, 1.0};

/* Tells whether every component of c is finite and stays finite as the image's float:
 * a double beyond FLT_MAX (3.4e38) is finite but would be stored as infinity. */
static bool fits_image(Color c)
{
    return fabs(c.r) <= FLT_MAX && fabs(c.g) <= FLT_MAX && fabs(c.b) <= FLT_MAX;
}

/* Renders rows until none are left, then adds this thread's counts to the crew's total. */
static void render_rows(Crew *s)
{
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
    RenderResult *r = &s->total;
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
}

/* The work of render_call's one thread. */
static void call_fn(Crew *crew)
{
    crew->fn(crew->arg);
}

/* Sets up crew to do work, with its waiting thread as its only owner. */
static void crew_init(Crew *crew, void (*work)(Crew *crew))
{
    memset(crew, 0, sizeof *crew);
    pthread_mutex_init(&crew->lock, NULL);
    pthread_condattr_t attr;
    pthread_condattr_init(&attr);
    pthread_condattr_setclock(&attr, CLOCK_MONOTONIC);
    pthread_cond_init(&crew->finished, &attr);
    pthread_condattr_destroy(&attr);
    crew->owners = 1;
    crew->work = work;
}

/* Frees what crew_init and the work set up in crew, but not crew itself. */
static void crew_destroy(Crew *crew)
{
    if (crew->progress_started)
        progress_finish(&crew->progress);
    pthread_cond_destroy(&crew->finished);
    pthread_mutex_destroy(&crew->lock);
}

/* Gives up one owner's share of the crew (lock held); frees it when it was the last. */
static void crew_leave(Crew *crew)
{
    bool last = --crew->owners == 0;
    pthread_mutex_unlock(&crew->lock);
    if (!last)
        return;
    crew_destroy(crew);
    free(crew);
}

/* A worker: does the crew's work, says so, and leaves the crew. */
static void *crew_worker(void *arg)
{
    Crew *crew = arg;
    crew->work(crew);
    pthread_mutex_lock(&crew->lock);
    crew->running--;
    pthread_cond_signal(&crew->finished);
    crew_leave(crew);
    atomic_fetch_sub(&threads_alive, 1);
    return NULL;
}

/* Starts up to count workers of the crew, with the stack RENDER_STACK_SIZE (or, if that
 * cannot be had, the default one); returns how many started, into tid. */
static int crew_start(Crew *crew, int count, pthread_t *tid)
{
    pthread_attr_t attr;
    bool have_attr = pthread_attr_init(&attr) == 0;
    bool sized = have_attr && pthread_attr_setstacksize(&attr, RENDER_STACK_SIZE) == 0;
    int started = 0;
    while (started < count) {
        pthread_mutex_lock(&crew->lock);
        crew->running++;
        crew->owners++;
        pthread_mutex_unlock(&crew->lock);
        atomic_fetch_add(&threads_alive, 1);
        int err = pthread_create(&tid[started], sized ? &attr : NULL, crew_worker, crew);
        if (err != 0 && sized)
            err = pthread_create(&tid[started], NULL, crew_worker, crew);
        if (err != 0) {
            /* A thread that cannot start is simply not there. */
            atomic_fetch_sub(&threads_alive, 1);
            pthread_mutex_lock(&crew->lock);
            crew->running--;
            crew->owners--;
            pthread_mutex_unlock(&crew->lock);
            break;
        }
        started++;
    }
    if (have_attr)
        pthread_attr_destroy(&attr);
    return started;
}

/* Waits for the crew's started workers to finish, and leaves the crew. After a stop
 * request, waits at most RENDER_STOP_GRACE more: workers still busy then are detached
 * and given up. Returns false when it gave some up; *total gets the counts of the
 * workers that finished. */
static bool crew_wait(Crew *crew, pthread_t *tid, int started, RenderResult *total)
{
    double stop_seen = 0;
    pthread_mutex_lock(&crew->lock);
    while (crew->running > 0) {
        if (stop_requested()) {
            double now = clock_now();
            if (stop_seen == 0)
                stop_seen = now;
            else if (now - stop_seen >= RENDER_STOP_GRACE)
                break;
        }
        /* A signal handler cannot signal a condition variable: look at the stop request
         * every RENDER_POLL_INTERVAL. */
        struct timespec until;
        clock_gettime(CLOCK_MONOTONIC, &until);
        until.tv_nsec += (long)(RENDER_POLL_INTERVAL * 1e9);
        if (until.tv_nsec >= 1000000000L) {
            until.tv_sec++;
            until.tv_nsec -= 1000000000L;
        }
        pthread_cond_timedwait(&crew->finished, &crew->lock, &until);
    }
    bool all_done = crew->running == 0;
    if (total != NULL)
        *total = crew->total;
    crew_leave(crew);
    for (int k = 0; k < started; k++) {
        if (all_done)
            pthread_join(tid[k], NULL);
        else
            pthread_detach(tid[k]);
    }
    return all_done;
}

/* Fills img by calling job->pixel for every pixel on job->threads threads. As every
 * pixel is computed by itself and stored in its own place, the image is the same
 * whatever the number of threads and whichever thread renders which row.
 *
 * The calling thread only waits: so a stop request (stop.h) ends the wait within
 * RENDER_STOP_GRACE even when a pixel takes minutes. Workers finish the pixel they are
 * on; those still busy after the grace are given up (result->abandoned): they go on
 * running, writing img and reading job->ctx, which the caller must then leave alone and
 * end the process at once (_exit), writing nothing. */
void render_image(Image *img, const RenderJob *job, RenderResult *result)
{
    memset(result, 0, sizeof *result);
    result->first_nonfinite_x = INT_MAX;
    result->first_nonfinite_y = INT_MAX;
    double start = clock_now();
    int threads = job->threads < 1 ? 1 : job->threads;
    if (threads > RENDER_MAX_THREADS)
        threads = RENDER_MAX_THREADS;

    /* The crew outlives this call if workers are given up; without memory for it, this
     * thread renders alone with one on its stack. */
    Crew local, *crew = malloc(sizeof *crew);
    crew_init(crew != NULL ? crew : &local, render_rows);
    Crew *c = crew != NULL ? crew : &local;
    c->img = img;
    c->job = job;
    c->total = *result;
    atomic_init(&c->next_row, 0);
    atomic_init(&c->rows_done, 0);
    progress_start(&c->progress, img->height, job->progress);
    c->progress_started = true;
    pthread_t tid[RENDER_MAX_THREADS];
    int started = crew != NULL ? crew_start(crew, threads, tid) : 0;
    if (started == 0)
        render_rows(c); /* no thread at all: this one renders */
    if (crew != NULL) {
        result->abandoned = !crew_wait(crew, tid, started, result);
    } else {
        *result = local.total;
        crew_destroy(&local);
    }
    result->seconds = clock_now() - start;
    result->stopped = stop_requested();
}

/* Calls fn(arg) on a thread with the render threads' stack and waits for it, as
 * render_image waits for its workers: true when fn returned; false when a stop was
 * requested and fn was still running RENDER_STOP_GRACE later, and was given up (it goes
 * on, with arg: the caller must end the process at once). Without threads, or memory,
 * fn runs on the calling thread. */
bool render_call(void (*fn)(void *arg), void *arg)
{
    Crew *crew = malloc(sizeof *crew);
    if (crew == NULL) {
        fn(arg);
        return true;
    }
    crew_init(crew, call_fn);
    crew->fn = fn;
    crew->arg = arg;
    pthread_t tid;
    int started = crew_start(crew, 1, &tid);
    if (started == 0)
        fn(arg);
    return crew_wait(crew, &tid, started, NULL);
}

/* Tells whether no thread of a render or call is still running: after one was given up,
 * once it has ended (for tests). */
bool render_idle(void)
{
    return atomic_load(&threads_alive) == 0;
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
