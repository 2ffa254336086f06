/* statcompare.c: a render held against a statistical reference: the exact, bias and noise tests. */
#include "statcompare.h"

#include <math.h>
#include <stdlib.h>

#include "statexact.h"

/* The value of channel k of img in the space compared: a code value (a PNG's as read,
 * a linear image's as raytra's PNG writer would encode it) or linear. */
static double value_of(const Image *img, long k, bool codes, bool png)
{
    double x = img->pixels[k];
    if (!codes || !isfinite(x))
        return x;
    return png ? x * 255.0 : image_encode_8bit(x, PNG_ENCODING_SRGB);
}

/* The exact test of pixel (x, y), and the sums of its noisy channels into the tests of
 * its block and of the image. */
static void test_pixel(const McRef *ref, const Image *img, bool png, StatDiff *d, const int *near,
                       int x, int y)
{
    const float *mean = ref->plane[d->codes ? MCREF_CODE : MCREF_MEAN];
    const float *var = ref->plane[d->codes ? MCREF_CODE_VAR : MCREF_VAR];
    double inflate = 1 + 1.0 / ref->mean_samples; /* the reference's mean is noisy too */
    long at = (long)y * img->width + x;
    bool differs = false;
    int quiet = 0;
    for (int c = 0; c < 3; c++) {
        long k = 3 * at + c;
        double s = value_of(img, k, d->codes, png), m = mean[k];
        if (!isfinite(s)) {
            d->nonfinite++;
            s = m;
        }
        double raw = fabs(s - m) / (d->codes ? 255.0 : 1.0);
        d->max[c] = fmax(d->max[c], raw);
        d->sum += raw, d->sum2 += raw * raw;
        /* By the "ok" standard the light's random points make noise where raytra's
         * correlated ones make none: every pixel is tested for bias, with the variance
         * the image shows. */
        if (var[k] > 0 || d->standard == STATDIFF_OK) {
            double v = var[k] * inflate, q = statbias_floor_variance(d->codes, m);
            statbias_add(&d->tests[3 * ((y / STATDIFF_BLOCK) * d->nx + x / STATDIFF_BLOCK) + c],
                         d->codes, s, m, v, q);
            statbias_add(&d->global[c], d->codes, s, m, v, q);
        } else {
            quiet++;
            differs = differs || fabs(s - m) > statexact_tolerance(d->codes, m);
        }
    }
    if (quiet == 0)
        return;
    bool fringe = near[at] > 0;
    if (fringe)
        d->fringe_channels += quiet;
    if (!differs)
        return;
    d->mark[at] = 1;
    if (fringe)
        d->fringe++;
    else if (d->deep++ == 0)
        d->deep_x = x, d->deep_y = y;
}

/* Compares img with ref: the exact test of the pixels without noise; the bias z-tests of
 * the blocks and of the whole image, corrected by Holm's procedure; the noise ratios;
 * false when out of memory. */
bool statcompare_image(const McRef *ref, const Image *img, bool png, StatStandard standard,
                       StatDiff *d)
{
    /* At P = 1 a pixel is one sample, lit or not: its sums are far from normal in the far
     * tail, and a code value's bounded range bounds it (Bernstein). */
    bool bounded = ref->p == 1;
    *d = (StatDiff){.codes = png || bounded,
                    .bounded = bounded,
                    .standard = standard,
                    .noise = {.worst = {.ratio = -1}}};
    d->nx = (img->width + STATDIFF_BLOCK - 1) / STATDIFF_BLOCK;
    d->ny = (img->height + STATDIFF_BLOCK - 1) / STATDIFF_BLOCK;
    d->count = 3 * d->nx * d->ny;
    long pixels = (long)img->width * img->height;
    d->tests = calloc((size_t)d->count, sizeof *d->tests);
    d->mark = calloc((size_t)pixels, 1);
    int *near = malloc((size_t)pixels * sizeof *near);
    BlockTest **order = calloc((size_t)d->count + 3, sizeof *order);
    if (d->tests == NULL || d->mark == NULL || near == NULL || order == NULL ||
        !statexact_near_noise(ref, d->codes, near)) {
        free(near);
        free(order);
        return false;
    }
    for (int by = 0, k = 0; by < d->ny; by++)
        for (int bx = 0; bx < d->nx; bx++)
            for (int c = 0; c < 3; c++, k++)
                d->tests[k] = (BlockTest){.bx = bx, .by = by, .c = c};
    for (int c = 0; c < 3; c++)
        d->global[c] = (BlockTest){.bx = -1, .by = -1, .c = c};
    for (int y = 0; y < img->height; y++)
        for (int x = 0; x < img->width; x++)
            test_pixel(ref, img, png, d, near, x, y);
    free(near);
    d->fringe_limit = statexact_fringe_limit(d->fringe_channels);
    /* By the "ok" standard the bias test may take the variance the image shows. */
    bool own = standard == STATDIFF_OK;
    double pixel_df = ref->variance_samples - 1;
    for (int k = 0; k < d->count; k++) {
        BlockTest *t = &d->tests[k];
        statbias_finish(t, d->codes, bounded, pixel_df, own);
        order[k] = t;
        if (fabs(t->z) > fabs(d->tests[d->worst].z))
            d->worst = k;
    }
    for (int c = 0; c < 3; c++) {
        statbias_finish(&d->global[c], d->codes, bounded, pixel_df, own);
        order[d->count + c] = &d->global[c];
    }
    statnoise_image(d->tests, d->nx, d->ny, &d->noise);
    int tests = d->count + 3;
    d->rejected = statbias_holm(order, tests);
    d->z_critical = statbias_critical(tests);
    free(order);
    return true;
}

/* Frees what statcompare_image allocated in d, whether it succeeded or not. */
void statcompare_free(StatDiff *d)
{
    free(d->tests);
    free(d->mark);
}
