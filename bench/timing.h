/* timing.h: the benchmark's clock, and its ray sets traced by threads and timed pass by pass. */
#ifndef RAYTRA_TIMING_H
#define RAYTRA_TIMING_H

#include <stdatomic.h>
#include <stdbool.h>

#include "baseline.h"
#include "baseline_tinybvh.h"
#include "bvh.h"

/* The most jobs timing_rates takes turns with. */
#define TIMING_MAX_JOBS 8

/* Who traces: raytra's BVH, brute force, the Embree baseline or a tinybvh one. */
typedef enum { BY_BVH, BY_BRUTE_FORCE, BY_BASELINE, BY_TINYBVH } Tracer;

/* A set of rays to trace, by whom, and the counters its threads share. */
typedef struct {
    Tracer by;
    const Bvh *bvh;
    const Baseline *baseline;
    const TinyBaseline *tiny;
    const BenchRay *rays;
    long count;
    bool shadow;
    atomic_long next;
    atomic_long hits;
} Job;

double timing_now(void);
void timing_rates(Job **jobs, const int *threads, int n, double *rate, long *hits);

#endif
