/* agree.h: why tinybvh counts other hits than raytra: the rays the two disagree on, one by one. */
#ifndef RAYTRA_AGREE_H
#define RAYTRA_AGREE_H

#include <stdbool.h>

#include "baseline_tinybvh.h"
#include "bvh.h"

/* tinybvh's Moller-Trumbore test takes a triangle whose determinant is under this, in
 * absolute value, for one the ray runs parallel to, and misses it. */
#define TINY_PARALLEL 1e-6f

/* The rays that raytra and a baseline answer differently. */
typedef struct {
    long missed; /* raytra hits (or finds blocked), the baseline does not */
    long flat;   /* of those, the rays whose first triangle in raytra is under TINY_PARALLEL */
    long extra;  /* the baseline hits (or finds blocked), raytra does not */
} Disagreement;

Disagreement agree_tiny(const Bvh *bvh, const TinyBaseline *tiny, const BenchRay *rays, long n,
                        bool shadow);

#endif
