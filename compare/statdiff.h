/* statdiff.h: judging a Monte Carlo render against a statistical reference, by a bias and a noise
 * test. */
#ifndef RAYTRA_STATDIFF_H
#define RAYTRA_STATDIFF_H

#include <stdbool.h>

#include "image.h"
#include "imgfile.h"
#include "mcref.h"
#include "statstandard.h"

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
int statdiff_run(const StatDiffRequest *req);

#endif
