/* statnoise.h: the noise test: is a render as noisy as raytra's at its P and S, in each square? */
#ifndef RAYTRA_STATNOISE_H
#define RAYTRA_STATNOISE_H

#include "statbias.h"
#include "statstandard.h"

/* The noise test: the RMS of the residual over the expected one, over the image's noisy
 * squares of 16 x 16 pixels, at least STATDIFF_NOISE_LOW (less: fewer samples than the
 * noise says, such as more samples than asked, a denoiser or the mean image), and at
 * most the standard's bound over the image and in any one square (calibrated,
 * docs/grading.md). */
#define STATDIFF_NOISE_LOW 0.65
#define STATDIFF_GOOD_IMAGE 1.6
#define STATDIFF_GOOD_BLOCK 3.5
#define STATDIFF_OK_IMAGE 3.0
#define STATDIFF_OK_BLOCK 6.0

/* The noise test looks at squares of NOISE_SPAN x NOISE_SPAN blocks (16 x 16 pixels) with
 * noise on NOISE_PIXELS pixels at least in effect: fewer say too little. A squared residual
 * counts at most NOISE_CAP^2 times its expected variance (winsorised). */
#define NOISE_SPAN 2
#define NOISE_PIXELS 16
#define NOISE_CAP 4

/* The noise test of one channel of a square of NOISE_SPAN x NOISE_SPAN blocks. */
typedef struct {
    int bx, by, c; /* its first block, the channel */
    double ratio;  /* the residual's RMS over the expected one */
} NoiseTest;

/* The noise test of a whole image, over its squares with noise enough. */
typedef struct {
    double ratio;    /* the residual's RMS over the expected one, noisy squares */
    int noisy;       /* noise tests made: squares with noise enough */
    NoiseTest worst; /* the one of largest ratio (ratio -1 when none) */
    double r2, v;    /* the noise tests' sums */
} ImageNoise;

void statnoise_image(const BlockTest *tests, int nx, int ny, ImageNoise *noise);
void statnoise_bounds(StatStandard standard, double *image, double *square);

#endif
