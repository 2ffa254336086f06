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

/* How hard the baseline's build works, as Embree's RTC_BUILD_QUALITY_*: HIGH builds a
 * spatial split BVH (a triangle may be in several leaves); MEDIUM, Embree's default, an
 * SAH tree without them that keeps each triangle in one leaf, as raytra's does; LOW, a
 * two-level structure for scenes that change, quicker to build still. */
typedef enum { BASELINE_HIGH, BASELINE_MEDIUM, BASELINE_LOW } BaselineQuality;

bool baseline_available(void);
Baseline *baseline_build(const Scene *scene, BaselineQuality quality, double *build_ms);
/* Traces rays[begin, end): closest hits (counting them) or occlusion (counting the blocked). */
long baseline_trace(const Baseline *b, const BenchRay *rays, long begin, long end, bool shadow);
void baseline_free(Baseline *b);

#endif
