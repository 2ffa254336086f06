/* statbias.h: the bias test of a block of pixels, or of a whole image, against the reference. */
#ifndef RAYTRA_STATBIAS_H
#define RAYTRA_STATBIAS_H

#include <stdbool.h>

/* The side of the square blocks of pixels the bias test compares. */
#define STATDIFF_BLOCK 8
/* The family-wise error rate of the bias test: with the exact test's (STATDIFF_ALPHA_EXACT,
 * statexact.h), the chance that a correct render of one scene fails (docs/grading.md
 * measures it). */
#define STATDIFF_ALPHA 0.0001

/* The test of one channel of one block (or of the whole image). */
typedef struct {
    int bx, by, c; /* the block's column and row of blocks (-1: the whole image), channel */
    int n;         /* its pixels with noise, which the test sums */
    double diff;   /* their mean difference, image minus reference */
    double se;     /* its standard error */
    double z, p;   /* the z-score of p, beyond the rounding allowance; its p-value */
    bool rejected; /* biased, by Holm's procedure */
    /* The sums the test and the noise test make over the block: differences, squared
     * differences, reference means, variances with their floors, floors, the reference's
     * variances and their squares; the largest deviation either way the range allows
     * (codes). */
    double sum_d, sum_d2, sum_m, sum_v, floors, noise, noise2, up, down;
} BlockTest;

double statbias_floor_variance(bool codes, double m);
double statbias_allowance(bool codes, double m);
void statbias_add(BlockTest *t, bool codes, double s, double m, double v, double q);
void statbias_finish(BlockTest *t, bool codes, bool bounded, double pixel_df, bool own);
int statbias_holm(BlockTest **order, int count);
double statbias_critical(int count);

#endif
