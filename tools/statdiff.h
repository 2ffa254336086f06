/* statdiff.h: judging a Monte Carlo render against a statistical reference, by a bias and a noise
 * test. */
#ifndef RAYTRA_STATDIFF_H
#define RAYTRA_STATDIFF_H

#include <stdbool.h>

#include "imgfile.h"

/* The side of the square blocks of pixels the bias test compares. */
#define STATDIFF_BLOCK 8
/* The family-wise error rate of the bias test: the chance that a correct render fails it. */
#define STATDIFF_ALPHA 0.001
/* The noise test: the RMS of the residual at most this many times the expected one, over
 * the whole image's noisy squares of 16 x 16 pixels, and in any one of them (statdiff.c;
 * calibrated on raytra's own renders, docs/grading.md). */
#define STATDIFF_NOISE_IMAGE 1.25
#define STATDIFF_NOISE_BLOCK 2.0

/* What imgdiff asks: the reference and the image, the pictures to draw, how to print. */
typedef struct {
    const char *reference, *image;
    ImgFileKind kind; /* the image's: a PNG is judged by its 8-bit code values */
    const char *diff_path, *diff_thumb, *thumb_path; /* or NULL */
    bool quiet, machine;
} StatDiffRequest;

int statdiff_run(const StatDiffRequest *req);

#endif
