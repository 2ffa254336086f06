/* strata.h: where sample points go in a square: at random, jittered, or in shuffled strata. */
#ifndef RAYTRA_STRATA_H
#define RAYTRA_STRATA_H

#include <stdbool.h>

#include "rng.h"

/* How the sample points of a pixel and of a light are placed (--sampling). */
typedef enum {
    SAMPLING_RANDOM,    /* every point uniform over the whole square, independently */
    SAMPLING_JITTERED,  /* one uniform point in each of n x n sub-squares */
    SAMPLING_CORRELATED /* jittered, and with S = 1 the light's strata follow the pixel's */
} Sampling;

bool strata_sampling_from_name(const char *name, Sampling *sampling);
void strata_point(Sampling sampling, Rng *rng, int k, int n, double *u, double *v);
void strata_shuffle(Rng *rng, int *perm, int count);

#endif
