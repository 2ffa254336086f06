/* baseline_tinybvh.h: the benchmark's peers of raytra's BVH: tinybvh's binary BVHs, same rays. */
#ifndef RAYTRA_BASELINE_TINYBVH_H
#define RAYTRA_BASELINE_TINYBVH_H

#include <stdbool.h>

#include "baseline.h"

/* tinybvh's two binary layouts, built on one thread over the same triangles in float:
 * BVH, 32-byte nodes of one box each (Wald's layout; a node's two children are tested
 * in scalar code), from tinybvh's reference builder (BVH::Build, binned SAH, 8 bins);
 * and BVH_SoA, 64-byte nodes holding their two children's boxes side by side, tested
 * with SSE as raytra's are in double, converted from the same tree built by BuildAVX. */
typedef enum { TINY_BVH, TINY_BVH_SOA } TinyLayout;

typedef struct TinyBaseline TinyBaseline;

bool tiny_available(void);
/* Builds the layout over the scene's triangles; *build_ms includes rounding them to float. */
TinyBaseline *tiny_build(const Scene *scene, TinyLayout layout, double *build_ms);
/* Traces rays[begin, end): closest hits (counting them) or occlusion (counting the blocked). */
long tiny_trace(const TinyBaseline *b, const BenchRay *rays, long begin, long end, bool shadow);
void tiny_free(TinyBaseline *b);

#endif
