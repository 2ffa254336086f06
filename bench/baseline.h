/* baseline.h: the Embree baseline of the benchmark: the same rays, traced by Embree 3. */
#ifndef RAYTRA_BASELINE_H
#define RAYTRA_BASELINE_H

#include <stdbool.h>

#include "ray.h"
#include "scene.h"

/* A ray of a benchmark's set: where it starts, its direction, and how far it may go. */
typedef struct {
    Ray ray;
    double tmax;
} BenchRay;

typedef struct Baseline Baseline;

bool baseline_available(void);
Baseline *baseline_build(const Scene *scene, double *build_ms);
/* Traces rays[begin, end): closest hits (counting them) or occlusion (counting the blocked). */
long baseline_trace(const Baseline *b, const BenchRay *rays, long begin, long end, bool shadow);
void baseline_free(Baseline *b);

#endif
