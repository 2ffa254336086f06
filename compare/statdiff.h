/* statdiff.h: judging a Monte Carlo render against a statistical reference, by a bias and a noise
 * test. */
#ifndef RAYTRA_STATDIFF_H
#define RAYTRA_STATDIFF_H

#include <stdbool.h>

#include "image.h"
#include "imgfile.h"
#include "mcref.h"

/* The side of the square blocks of pixels the bias test compares. */
#define STATDIFF_BLOCK 8
/* The family-wise error rate of the bias test, and the error rate of the exact test of the
 * pixels the references saw without noise: together the chance that a correct render of
 * one scene fails (docs/grading.md measures it). */
#define STATDIFF_ALPHA 0.0001
#define STATDIFF_ALPHA_EXACT 0.00001
/* The noise test: the RMS of the residual over the expected one, over the image's noisy
 * squares of 16 x 16 pixels, at least STATDIFF_NOISE_LOW (less: fewer samples than the
 * noise says, such as more samples than asked, a denoiser or the mean image), and at
 * most the standard's bound over the image and in any one square (calibrated,
 * docs/grading.md). */
#define STATDIFF_NOISE_LOW 0.75
#define STATDIFF_GOOD_IMAGE 1.6
#define STATDIFF_GOOD_BLOCK 3.5
#define STATDIFF_OK_IMAGE 3.0
#define STATDIFF_OK_BLOCK 6.0

/* The course's two standards of a soft shadow: "good", stratified or correlated light
 * samples (raytra's); "ok", random points on the light. */
typedef enum { STATDIFF_GOOD, STATDIFF_OK } StatStandard;

/* What imgdiff asks: the reference and the image, the pictures to draw, how to print. */
typedef struct {
    const char *reference, *image;
    ImgFileKind kind; /* the image's: a PNG is judged by its 8-bit code values */
    const char *diff_path, *diff_thumb, *thumb_path; /* or NULL */
    bool quiet, machine;
    StatStandard standard;
} StatDiffRequest;

/* A verdict in short, for tools that judge many renders (the calibration). */
typedef struct {
    bool pass;
    char test[16];      /* the failed test: bias, exact, noise, smooth, nonfinite; or "" */
    double z_fraction;  /* the largest |z| of the bias test over its critical value */
    double noise_image; /* the residual's RMS over the expected one */
    double noise_block; /* the same in the noisiest square */
    int exact_differ;   /* pixels the references saw without noise that differ */
} StatVerdict;

bool statdiff_judge(const McRef *ref, const Image *img, bool codes, StatStandard standard,
                    StatVerdict *out);
bool statdiff_standard_from_name(const char *name, StatStandard *standard);
int statdiff_run(const StatDiffRequest *req);

#endif
