/* strata.c: stratified ("jittered") sampling of the unit square (textbook 13.4), shuffles. */
#include "strata.h"

#include <string.h>

/* Reads a --sampling name into sampling; NULL means the default, correlated. */
bool strata_sampling_from_name(const char *name, Sampling *sampling)
{
    static const char *const names[] = {"random", "jittered", "correlated"};
    if (name == NULL) {
        *sampling = SAMPLING_CORRELATED;
        return true;
    }
    for (int k = 0; k < 3; k++)
        if (strcmp(name, names[k]) == 0) {
            *sampling = (Sampling)k;
            return true;
        }
    return false;
}

/* starter: todo */
/* Sets (u, v) to sample k of n x n in the unit square [0,1)^2. Jittered: the square is cut
 * into n x n sub-squares, k counting them row by row, and the point is uniform within
 * sub-square k, so that the n^2 points cover the square evenly. Correlated places the
 * point as jittered does (which light stratum goes with which pixel stratum is the
 * caller's: sum_samples pairs them through a shuffle). Random: uniform over the whole
 * square, whatever k, so that points may clump and leave holes. */
void strata_point(Sampling sampling, Rng *rng, int k, int n, double *u, double *v)
{
    double ru = rng_uniform(rng), rv = rng_uniform(rng);
    if (sampling == SAMPLING_RANDOM) {
        *u = ru;
        *v = rv;
        return;
    }
    *u = (k % n + ru) / n;
    *v = (k / n + rv) / n;
}

/* starter: todo */
/* Fills perm with 0 .. count-1 in a uniformly random order (Fisher-Yates). */
void strata_shuffle(Rng *rng, int *perm, int count)
{
    for (int k = 0; k < count; k++)
        perm[k] = k;
    for (int k = count - 1; k > 0; k--) {
        int other = (int)rng_below(rng, (uint32_t)k + 1);
        int keep = perm[k];
        perm[k] = perm[other];
        perm[other] = keep;
    }
}
