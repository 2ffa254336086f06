/* statcompare.h: a render held against a statistical reference: the exact, bias and noise tests. */
#ifndef RAYTRA_STATCOMPARE_H
#define RAYTRA_STATCOMPARE_H

#include <stdbool.h>

#include "image.h"
#include "mcref.h"
#include "statbias.h"
#include "statnoise.h"
#include "statstandard.h"

/* The comparison of a whole image. */
typedef struct {
    bool codes;   /* compared as 8-bit code values (a PNG, or any image at P = 1) */
    bool bounded; /* the bias test bounds its tails by Bernstein's inequality (P = 1) */
    StatStandard standard;
    int nx, ny, count; /* blocks across and down; block tests (blocks x channels) */
    BlockTest *tests;
    BlockTest global[3];      /* the whole image's test, a channel each */
    int rejected, worst;      /* tests found biased; the block test of largest |z| */
    double z_critical;        /* the |z| beyond which the worst test is rejected */
    ImageNoise noise;         /* the noise test over the image's squares */
    double max[3], sum, sum2; /* raw differences, on a 0 to 1 scale, for the figures */
    long nonfinite;
    /* The exact test: pixels the references saw without noise that differ, away from the
     * noise (deep) and on its fringe; the fringe's channels without noise; the fewest
     * differing fringe pixels that fail; the first deep one; each pixel's mark. */
    long deep, fringe, fringe_channels, fringe_limit;
    int deep_x, deep_y;
    unsigned char *mark; /* a pixel: 1 differs, exactly compared; 0 otherwise */
} StatDiff;

bool statcompare_image(const McRef *ref, const Image *img, bool png, StatStandard standard,
                       StatDiff *d);
void statcompare_free(StatDiff *d);

#endif
