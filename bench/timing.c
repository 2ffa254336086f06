/* timing.c: the benchmark's clock, and its ray sets traced by threads and timed pass by pass. */
#include "timing.h"

#include <math.h>
#include <pthread.h>
#include <time.h>

#include "world.h"

/* Rays traced in one go by a thread before it takes the next batch. */
#define BATCH 4096

/* Returns the seconds of a monotonic clock. */
double timing_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* Traces batches of the job's rays until none are left. */
static void *trace_worker(void *arg)
{
    Job *job = arg;
    long hits = 0;
    for (;;) {
        long begin = atomic_fetch_add(&job->next, BATCH);
        if (begin >= job->count)
            break;
        long end = begin + BATCH < job->count ? begin + BATCH : job->count;
        if (job->by == BY_BASELINE) {
            hits += baseline_trace(job->baseline, job->rays, begin, end, job->shadow);
            continue;
        }
        if (job->by == BY_TINYBVH) {
            hits += tiny_trace(job->tiny, job->rays, begin, end, job->shadow);
            continue;
        }
        for (long k = begin; k < end; k++) {
            const BenchRay *r = &job->rays[k];
            Hit hit;
            long tests = 0;
            if (job->by == BY_BRUTE_FORCE)
                hits += world_hit(job->bvh->scene, r->ray, 0, r->tmax, &hit);
            else if (job->shadow)
                hits += bvh_blocked(job->bvh, r->ray, 0, r->tmax);
            else
                hits += bvh_hit(job->bvh, r->ray, 0, r->tmax, &hit, &tests);
        }
    }
    atomic_fetch_add(&job->hits, hits);
    return NULL;
}

/* Traces all of job's rays once with threads threads; returns the seconds it took. */
static double trace_pass(Job *job, int threads)
{
    atomic_store(&job->next, 0);
    atomic_store(&job->hits, 0);
    pthread_t tid[8];
    double start = timing_now();
    for (int t = 1; t < threads; t++)
        pthread_create(&tid[t], NULL, trace_worker, job);
    trace_worker(job);
    for (int t = 1; t < threads; t++)
        pthread_join(tid[t], NULL);
    return timing_now() - start;
}

/* Traces jobs[0 .. n) (n at most TIMING_MAX_JOBS) with threads[k] threads each, taking turns pass
 * by pass, so that whatever else the machine does slows them alike: at least three passes each, and
 * on until each has run 0.3 s in all (20 passes at most). Sets rate[k] to millions of rays a second
 * of job k's fastest pass, and hits[k] to its hits. */
void timing_rates(Job **jobs, const int *threads, int n, double *rate, long *hits)
{
    double best[TIMING_MAX_JOBS], total[TIMING_MAX_JOBS] = {0};
    for (int k = 0; k < n; k++)
        best[k] = INFINITY;
    for (int pass = 0; pass < 20; pass++) {
        bool enough = pass >= 3;
        for (int k = 0; k < n; k++) {
            double s = trace_pass(jobs[k], threads[k]);
            best[k] = fmin(best[k], s);
            total[k] += s;
            enough = enough && total[k] >= 0.3;
        }
        if (enough)
            break;
    }
    for (int k = 0; k < n; k++) {
        rate[k] = jobs[k]->count / best[k] / 1e6;
        hits[k] = atomic_load(&jobs[k]->hits);
    }
}
