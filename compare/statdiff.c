/* statdiff.c: a render judged against a statistical reference: is it biased, is it too noisy? */
#include "statdiff.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "image.h"
#include "image_read.h"
#include "imgmap.h"
#include "mcref.h"

enum { EXIT_MATCH = 0, EXIT_DIFFER = 1, EXIT_TROUBLE = 2 };

/* The noise test looks at squares of NOISE_SPAN x NOISE_SPAN blocks (16 x 16 pixels) with
 * noise on NOISE_PIXELS pixels at least in effect: fewer say too little. A squared residual
 * counts at most NOISE_CAP^2 times its expected variance (winsorised). */
#define NOISE_SPAN 2
#define NOISE_PIXELS 16
#define NOISE_CAP 4
/* A pixel the references saw without noise is on the fringe of the noise when a pixel with
 * noise lies within FRINGE pixels of it (across or down): it may be one that varies
 * rarely, such as a penumbra's last pixel, lit by one render in a hundred. */
#define FRINGE 4
/* The chance that a pixel's 64 references agree and one more render differs: at most
 * max over q of q (1 - q)^64 = (1/65) (64/65)^64, whatever the chance q that it differs
 * (Good and Turing's missing mass: the render is the 65th of 65 alike). */
#define UNSEEN_CHANCE 0.005673

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

/* The noise test of one channel of a square of NOISE_SPAN x NOISE_SPAN blocks. */
typedef struct {
    int bx, by, c; /* its first block, the channel */
    double ratio;  /* the residual's RMS over the expected one */
} NoiseTest;

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
    double noise_image;       /* the residual's RMS over the expected one, noisy squares */
    int noisy;                /* noise tests made: squares with noise enough */
    NoiseTest noise_worst;    /* the one of largest ratio (ratio -1 when none) */
    double noise_r2, noise_v; /* the noise tests' sums */
    double max[3], sum, sum2; /* raw differences, on a 0 to 1 scale, for the figures */
    long nonfinite;
    /* The exact test: pixels the references saw without noise that differ, away from the
     * noise (deep) and on its fringe; the fringe's channels without noise; the fewest
     * differing fringe pixels that fail; the first deep one; each pixel's mark. */
    long deep, fringe, fringe_channels, fringe_limit;
    int deep_x, deep_y;
    unsigned char *mark; /* a pixel: 1 differs, exactly compared; 0 otherwise */
} StatDiff;

/* Returns the variance floor of a pixel whose reference value is m: in codes, a uniform
 * rounding error, 1/12 code^2; linear, the rounding of a half-float file (2^-11 relative,
 * doubled for safety), (2^-10 (|m| + 1/64))^2 / 12. */
static double floor_variance(bool codes, double m)
{
    double step = ldexp(fabs(m) + 1.0 / 64, -10);
    return codes ? 1.0 / 12 : step * step / 12;
}

/* Returns the rounding allowance of a block whose reference mean is m: the systematic
 * difference no test counts, one code (rounding, or a PNG written by truncation), or
 * 2^-10 (1 + |m|) linear. */
static double allowance(bool codes, double m)
{
    return codes ? 1.0 : ldexp(1 + fabs(m), -10);
}

/* Returns how far a value may be from the value m that every reference had and still be
 * the same: one code (rounding the other way, or truncation); linear, a half float's
 * rounding doubled, 2^-10 (|m| + 1/64). */
static double exact_tolerance(bool codes, double m)
{
    return codes ? 1.001 : ldexp(fabs(m) + 1.0 / 64, -10);
}

/* Returns the |z| whose two-sided p-value is p: the normal quantile, by bisection. */
static double z_of_p(double p)
{
    double lo = 0, hi = 40;
    for (int k = 0; k < 200; k++) {
        double mid = (lo + hi) / 2;
        if (erfc(mid / sqrt(2)) > p)
            lo = mid;
        else
            hi = mid;
    }
    return (lo + hi) / 2;
}

/* Returns Bernstein's bound on the chance that a sum of independent deviations of total
 * variance v, each at most b, reaches t: exp(-t^2 / (2 (v + b t / 3))). */
static double bernstein(double t, double v, double b)
{
    return t <= 0 ? 1 : exp(-t * t / (2 * (v + b * t / 3)));
}

/* Returns the upper tail of a count of independent rare events whose mean is at most mu:
 * the chance of k or more, by Chernoff's bound e^-mu (e mu / k)^k (1 when k <= mu). */
static double chernoff_tail(long k, double mu)
{
    if (k <= mu)
        return 1;
    if (mu <= 0)
        return 0;
    return exp(-mu + k * (1 + log(mu / k)));
}

/* Orders tests by p-value, smallest first (Holm's order). */
static int by_p(const void *a, const void *b)
{
    double p = (*(const BlockTest *const *)a)->p, q = (*(const BlockTest *const *)b)->p;
    return (p > q) - (p < q);
}

/* The value of channel k of img in the space compared: a code value (a PNG's as read,
 * a linear image's as raytra's PNG writer would encode it) or linear. */
static double value_of(const Image *img, long k, bool codes, bool png)
{
    double x = img->pixels[k];
    if (!codes || !isfinite(x))
        return x;
    return png ? x * 255.0 : image_encode_8bit(x, PNG_ENCODING_SRGB);
}

/* Adds pixel-channel k's difference from the reference to the sums of test t: its value
 * s, the reference's mean m and variance v of one render, the space's floor q. */
static void add_pixel(BlockTest *t, bool codes, double s, double m, double v, double q)
{
    double r = s - m;
    t->n++;
    t->sum_d += r, t->sum_d2 += r * r, t->sum_m += m, t->sum_v += v + q, t->floors += q;
    t->noise += v, t->noise2 += v * v;
    /* The range of a code value: a pixel is at most 255 - m brighter, m darker. */
    if (codes)
        t->up = fmax(t->up, 255 - m), t->down = fmax(t->down, m);
}

/* Completes test t from its sums: the mean difference beyond the rounding allowance over
 * its standard error, and its two-sided p-value; by the normal law, or with bounded
 * Bernstein's inequality over the range of a code value. The variance is the larger of
 * the reference's and the one the image's differences show (n / (n - 1) times their sum
 * of squares about their mean), so that an unbiased image noisier than raytra's (the
 * "ok" standard) is not called biased. */
static void finish_test(BlockTest *t, bool codes, bool bounded)
{
    if (t->n == 0) {
        t->p = 1;
        return;
    }
    t->diff = t->sum_d / t->n;
    double spread = t->sum_d2 - t->sum_d * t->diff;
    double v = t->n > 1 ? fmax(t->sum_v, spread * t->n / (t->n - 1)) : t->sum_v;
    t->se = sqrt(v) / t->n;
    double excess = fmax(0, fabs(t->diff) - allowance(codes, t->sum_m / t->n));
    if (bounded) {
        double tail = excess * t->n;
        t->p = fmin(1, bernstein(tail, v, t->up) + bernstein(tail, v, t->down));
        t->z = copysign(t->p < 1 ? z_of_p(t->p) : 0, t->diff);
    } else {
        t->z = t->se > 0 ? excess / t->se : 0;
        /* With the image's own variance the ratio is Student's t of n - 1 degrees of
         * freedom: its normal equivalent, by Bailey's approximation. */
        double df = t->n - 1;
        if (v > t->sum_v && df >= 2)
            t->z = t->z * (1 - 1 / (4 * df)) / sqrt(1 + t->z * t->z / (2 * df));
        t->z = copysign(t->z, t->diff);
        t->p = erfc(fabs(t->z) / sqrt(2));
    }
}

/* Marks in noisy the pixels whose reference varies in some channel, and sets in near the
 * count of such pixels within FRINGE of each pixel (a summed-area table). */
static bool noise_near(const McRef *ref, bool codes, int *near)
{
    int w = ref->width, h = ref->height;
    const float *var = ref->plane[codes ? MCREF_CODE_VAR : MCREF_VAR];
    int *sum = calloc((size_t)(w + 1) * (h + 1), sizeof *sum);
    if (sum == NULL)
        return false;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            const float *v = &var[3 * ((long)y * w + x)];
            int noisy = v[0] > 0 || v[1] > 0 || v[2] > 0;
            sum[(long)(y + 1) * (w + 1) + x + 1] = noisy + sum[(long)y * (w + 1) + x + 1] +
                                                   sum[(long)(y + 1) * (w + 1) + x] -
                                                   sum[(long)y * (w + 1) + x];
        }
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            int x0 = x - FRINGE < 0 ? 0 : x - FRINGE, x1 = x + FRINGE + 1 > w ? w : x + FRINGE + 1;
            int y0 = y - FRINGE < 0 ? 0 : y - FRINGE, y1 = y + FRINGE + 1 > h ? h : y + FRINGE + 1;
            near[(long)y * w + x] = sum[(long)y1 * (w + 1) + x1] - sum[(long)y0 * (w + 1) + x1] -
                                    sum[(long)y1 * (w + 1) + x0] + sum[(long)y0 * (w + 1) + x0];
        }
    free(sum);
    return true;
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
            double v = var[k] * inflate, q = floor_variance(d->codes, m);
            add_pixel(&d->tests[3 * ((y / STATDIFF_BLOCK) * d->nx + x / STATDIFF_BLOCK) + c],
                      d->codes, s, m, v, q);
            add_pixel(&d->global[c], d->codes, s, m, v, q);
        } else {
            quiet++;
            differs = differs || fabs(s - m) > exact_tolerance(d->codes, m);
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

/* The noise test of channel c of the square of blocks from (bx, by): the residual's RMS
 * about each block's mean difference over the expected one (a bias, or a PNG written by
 * truncation, is not noise), or -1 when the square has too little noise to tell: noise
 * below the floors, or on fewer than NOISE_PIXELS pixels in effect ((sum v)^2 / sum v^2).
 * A block's squared residuals are winsorised at NOISE_CAP standard deviations on the
 * whole: one rare bright sample (a highlight) cannot make a square noisy. */
static NoiseTest test_noise(StatDiff *d, int bx, int by, int c)
{
    double r2 = 0, v = 0, floors = 0, noise = 0, noise2 = 0;
    for (int y = by; y < by + NOISE_SPAN && y < d->ny; y++)
        for (int x = bx; x < bx + NOISE_SPAN && x < d->nx; x++) {
            const BlockTest *t = &d->tests[3 * (y * d->nx + x) + c];
            double spread = t->n > 0 ? t->sum_d2 - t->sum_d * t->sum_d / t->n : 0;
            r2 += fmin(spread, NOISE_CAP * NOISE_CAP * t->sum_v), v += t->sum_v;
            floors += t->floors, noise += t->noise, noise2 += t->noise2;
        }
    NoiseTest n = {.bx = bx, .by = by, .c = c, .ratio = -1};
    if (noise > floors && noise * noise >= NOISE_PIXELS * noise2) {
        n.ratio = sqrt(r2 / v);
        d->noisy++;
        d->noise_r2 += r2, d->noise_v += v;
    }
    return n;
}

/* Compares img with ref: the exact test of the pixels without noise; the bias z-tests of
 * the blocks and of the whole image, corrected by Holm's procedure; the noise ratios;
 * false when out of memory. */
static bool statdiff_compare(const McRef *ref, const Image *img, bool png, StatStandard standard,
                             StatDiff *d)
{
    /* At P = 1 a pixel is one sample, lit or not: its sums are far from normal in the far
     * tail, and a code value's bounded range bounds it (Bernstein). */
    bool bounded = ref->p == 1;
    *d = (StatDiff){.codes = png || bounded,
                    .bounded = bounded,
                    .standard = standard,
                    .noise_worst = {.ratio = -1}};
    d->nx = (img->width + STATDIFF_BLOCK - 1) / STATDIFF_BLOCK;
    d->ny = (img->height + STATDIFF_BLOCK - 1) / STATDIFF_BLOCK;
    d->count = 3 * d->nx * d->ny;
    long pixels = (long)img->width * img->height;
    d->tests = calloc((size_t)d->count, sizeof *d->tests);
    d->mark = calloc((size_t)pixels, 1);
    int *near = malloc((size_t)pixels * sizeof *near);
    BlockTest **order = calloc((size_t)d->count + 3, sizeof *order);
    if (d->tests == NULL || d->mark == NULL || near == NULL || order == NULL ||
        !noise_near(ref, d->codes, near)) {
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
    /* The exact test's fringe: the fewest differing pixels whose chance is below its
     * error rate, when each differs at most UNSEEN_CHANCE a channel. */
    double mu = UNSEEN_CHANCE * d->fringe_channels;
    for (d->fringe_limit = (long)mu + 1; chernoff_tail(d->fringe_limit, mu) > STATDIFF_ALPHA_EXACT;)
        d->fringe_limit++;
    for (int k = 0; k < d->count; k++) {
        BlockTest *t = &d->tests[k];
        finish_test(t, d->codes, bounded);
        order[k] = t;
        if (fabs(t->z) > fabs(d->tests[d->worst].z))
            d->worst = k;
    }
    for (int c = 0; c < 3; c++) {
        finish_test(&d->global[c], d->codes, bounded);
        order[d->count + c] = &d->global[c];
    }
    for (int by = 0; by < d->ny; by += NOISE_SPAN)
        for (int bx = 0; bx < d->nx; bx += NOISE_SPAN)
            for (int c = 0; c < 3; c++) {
                NoiseTest n = test_noise(d, bx, by, c);
                if (n.ratio > d->noise_worst.ratio)
                    d->noise_worst = n;
            }
    d->noise_image = d->noise_v > 0 ? sqrt(d->noise_r2 / d->noise_v) : 0;
    /* Holm: the j-th smallest p-value (from 0) is rejected when it and all before it are
     * at most alpha / (count - j); the family-wise error rate is then at most alpha. */
    int tests = d->count + 3;
    qsort(order, (size_t)tests, sizeof *order, by_p);
    for (int j = 0; j < tests && order[j]->p <= STATDIFF_ALPHA / (tests - j); j++)
        order[j]->rejected = true, d->rejected++;
    d->z_critical = z_of_p(STATDIFF_ALPHA / tests);
    free(order);
    return true;
}

/* Writes the heat map of d: each block the colour of its largest |z| over its channels,
 * white at the critical value and beyond; black within the rounding allowance; a pixel
 * the references saw without noise that differs, white. */
static bool write_heat(const StatDiff *d, int width, int height, const StatDiffRequest *req)
{
    float *level = malloc((size_t)width * height * sizeof *level);
    if (level == NULL)
        return false;
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            const BlockTest *t = &d->tests[3 * ((y / STATDIFF_BLOCK) * d->nx + x / STATDIFF_BLOCK)];
            double z = fmax(fabs(t[0].z), fmax(fabs(t[1].z), fabs(t[2].z)));
            level[(long)y * width + x] = (float)(d->mark[(long)y * width + x] ? d->z_critical : z);
        }
    bool ok =
        imgmap_write_levels(level, width, height, d->z_critical, req->diff_path, req->diff_thumb);
    free(level);
    return ok;
}

/* Writes into text the block of test t, in pixels, y from the top; the whole image for
 * an image's test. */
static void block_text(const BlockTest *t, int width, int height, char *text, size_t size)
{
    if (t->bx < 0) {
        snprintf(text, size, "the whole image");
        return;
    }
    int x0 = t->bx * STATDIFF_BLOCK, y0 = t->by * STATDIFF_BLOCK;
    int x1 = x0 + STATDIFF_BLOCK - 1 < width ? x0 + STATDIFF_BLOCK - 1 : width - 1;
    int y1 = y0 + STATDIFF_BLOCK - 1 < height ? y0 + STATDIFF_BLOCK - 1 : height - 1;
    snprintf(text, size, "block (%d,%d)-(%d,%d)", x0, y0, x1, y1);
}

/* Writes into text the square of noise test n, in pixels, y from the top. */
static void square_text(const NoiseTest *n, int width, int height, char *text, size_t size)
{
    int side = NOISE_SPAN * STATDIFF_BLOCK, x0 = n->bx * STATDIFF_BLOCK,
        y0 = n->by * STATDIFF_BLOCK;
    snprintf(text, size, "(%d,%d)-(%d,%d)", x0, y0,
             x0 + side - 1 < width ? x0 + side - 1 : width - 1,
             y0 + side - 1 < height ? y0 + side - 1 : height - 1);
}

/* Returns the standard's bounds on the noise ratio, over the image and in a square. */
static void noise_bounds(StatStandard standard, double *image, double *square)
{
    *image = standard == STATDIFF_OK ? STATDIFF_OK_IMAGE : STATDIFF_GOOD_IMAGE;
    *square = standard == STATDIFF_OK ? STATDIFF_OK_BLOCK : STATDIFF_GOOD_BLOCK;
}

/* Returns the standard's name, as --standard takes it. */
static const char *standard_name(StatStandard standard)
{
    return standard == STATDIFF_OK ? "ok" : "good";
}

/* Sets *standard from its name, "good" or "ok"; false when it is neither. */
bool statdiff_standard_from_name(const char *name, StatStandard *standard)
{
    if (strcmp(name, "good") != 0 && strcmp(name, "ok") != 0)
        return false;
    *standard = strcmp(name, "ok") == 0 ? STATDIFF_OK : STATDIFF_GOOD;
    return true;
}

/* Returns the most biased test: the block test of largest |z|, or a whole image's test
 * when one is rejected and no block's is. */
static const BlockTest *worst_test(const StatDiff *d)
{
    const BlockTest *w = &d->tests[d->worst];
    for (int c = 0; c < 3; c++)
        if (d->global[c].rejected && !w->rejected)
            w = &d->global[c];
    return w;
}

/* Writes the verdict's reason into text and the failed test's name into test; returns
 * whether the image passes. Biased (bias, then exact) always fails; then too little
 * noise, then more than the standard allows. */
static bool verdict(const StatDiff *d, const McRef *ref, int width, int height, char *test,
                    char *text, size_t size)
{
    const BlockTest *w = worst_test(d);
    char where[64];
    block_text(w, width, height, where, sizeof where);
    const char *unit = d->codes ? "codes" : "(linear)";
    double most_image, most_square;
    noise_bounds(d->standard, &most_image, &most_square);
    const NoiseTest *n = d->noise_worst.ratio >= 0 ? &d->noise_worst : NULL;
    strcpy(test, "");
    if (d->nonfinite > 0) {
        strcpy(test, "nonfinite");
        snprintf(text, size, "%ld pixel values are not finite (NaN or infinite)", d->nonfinite);
    } else if (d->rejected > 0) {
        strcpy(test, "bias");
        snprintf(text, size,
                 "bias: %d of %d tests differ from the reference beyond chance (family-wise "
                 "%g); the worst, %s, %c: %s by %.3g %s, z = %.1f",
                 d->rejected, d->count + 3, STATDIFF_ALPHA, where, "RGB"[w->c],
                 w -> diff > 0 ? "brighter" : "darker", fabs(w->diff), unit, w->z);
    } else if (d->deep > 0 || d->fringe >= d->fringe_limit) {
        strcpy(test, "exact");
        if (d->deep > 0)
            snprintf(text, size,
                     "exact: %ld pixels differ where all %d renders of the reference agree, away "
                     "from any noise (the first at (%d,%d)): a correct render has the very same "
                     "values there",
                     d->deep, ref->variance_samples, d->deep_x, d->deep_y);
        else
            snprintf(text, size,
                     "exact: %ld pixels differ where all %d renders of the reference agree, next "
                     "to noisy ones (at most %ld allowed: a correct render has more with a "
                     "chance below %g)",
                     d->fringe, ref->variance_samples, d->fringe_limit - 1, STATDIFF_ALPHA_EXACT);
    } else if (n != NULL && d->noise_image < STATDIFF_NOISE_LOW) {
        strcpy(test, "smooth");
        snprintf(text, size,
                 "smooth: too little noise for P %d S %d: %.2f times raytra's over the image's "
                 "noisy squares (at least %.2f): more samples than asked, a denoiser, or an "
                 "average of renders?",
                 ref->p, ref->s, d->noise_image, STATDIFF_NOISE_LOW);
    } else if (n != NULL && d->noise_image > most_image) {
        strcpy(test, "noise");
        snprintf(text, size,
                 "noise: unbiased, but %.2f times as noisy as raytra's at P %d S %d over the "
                 "image's noisy squares, more than the \"%s\" standard allows (%.2f): fewer "
                 "samples than asked, or %s?",
                 d->noise_image, ref->p, ref->s, standard_name(d->standard), most_image,
                 d->standard == STATDIFF_OK ? "pixels not stratified"
                                            : "light samples not stratified");
    } else if (n != NULL && n->ratio > most_square) {
        strcpy(test, "noise");
        square_text(n, width, height, where, sizeof where);
        snprintf(text, size,
                 "noise: unbiased, but the square %s, %c, is %.2f times as noisy as raytra's at "
                 "P %d S %d, more than the \"%s\" standard allows (%.2f): %s?",
                 where, "RGB"[n->c], n -> ratio, ref -> p, ref -> s, standard_name(d->standard),
                 most_square,
                 d -> standard == STATDIFF_OK ? "pixels not stratified"
                                              : "pixels or light samples not stratified");
    } else {
        snprintf(text, size,
                 "converges to the reference: no block biased (largest |z| %.2f, critical %.2f), "
                 "noise %.2f times the expected (\"%s\" standard)",
                 fabs(w->z), d->z_critical, d->noise_image, standard_name(d->standard));
        return true;
    }
    return false;
}

/* Returns how many pixels of a block starting at x0 lie within an image extent wide. */
static int box_side(int x0, int extent)
{
    return x0 + STATDIFF_BLOCK <= extent ? STATDIFF_BLOCK : extent - x0;
}

/* Counts into *differing the pixels the verdict faults (those of rejected blocks, and
 * those compared exactly that differ) and sets box around them: x0, y0, x1, y1. */
static long faulted_pixels(const StatDiff *d, const Image *img, int box[4])
{
    long differing = 0;
    box[0] = img->width, box[1] = img->height, box[2] = box[3] = -1;
    for (int by = 0; by < d->ny; by++)
        for (int bx = 0; bx < d->nx; bx++) {
            const BlockTest *t = &d->tests[3 * (by * d->nx + bx)];
            bool biased = t[0].rejected || t[1].rejected || t[2].rejected;
            for (int y = by * STATDIFF_BLOCK;
                 y < by * STATDIFF_BLOCK + box_side(by * STATDIFF_BLOCK, img->height); y++)
                for (int x = bx * STATDIFF_BLOCK;
                     x < bx * STATDIFF_BLOCK + box_side(bx * STATDIFF_BLOCK, img->width); x++)
                    if (biased || d->mark[(long)y * img->width + x]) {
                        differing++;
                        box[0] = x < box[0] ? x : box[0], box[1] = y < box[1] ? y : box[1];
                        box[2] = x > box[2] ? x : box[2], box[3] = y > box[3] ? y : box[3];
                    }
        }
    return differing;
}

/* Prints the figures of d, in words or with --machine as NAME VALUE lines. */
static void print_figures(const StatDiff *d, const McRef *ref, const Image *img,
                          const StatDiffRequest *req, bool pass, const char *reason)
{
    long pixels = (long)img->width * img->height;
    int box[4];
    long differing = faulted_pixels(d, img, box);
    double mean = d->sum / (3.0 * pixels), rmse = sqrt(d->sum2 / (3.0 * pixels));
    const BlockTest *w = worst_test(d);
    const NoiseTest *n = d->noise_worst.ratio >= 0 ? &d->noise_worst : NULL;
    double most_image, most_square;
    noise_bounds(d->standard, &most_image, &most_square);
    char where[64];
    block_text(w, img->width, img->height, where, sizeof where);
    if (req->machine) {
        printf("mode statistics\nstandard %s\nsize %d %d\nmax %.9g %.9g %.9g\nmean %.9g\n"
               "rmse %.9g\npsnr %.9g\ndiffering %ld %ld\n",
               standard_name(d->standard), img->width, img->height, d->max[0], d->max[1], d->max[2],
               mean, rmse, -20 * log10(rmse), differing, pixels);
        if (differing > 0)
            printf("box %d %d %d %d\n", box[0], box[1], box[2], box[3]);
        printf("exact %ld %ld %ld\n", d->deep, d->fringe, d->fringe_limit);
        printf("bias_tests %d %d\nbias_worst %.6g %.6g %s %c\nnoise_image %.6g %.6g %.6g\n",
               d->rejected, d->count + 3, w->z, d->z_critical, where, "RGB"[w->c], d -> noise_image,
               STATDIFF_NOISE_LOW, most_image);
        if (n != NULL) {
            square_text(n, img->width, img->height, where, sizeof where);
            printf("noise_block %.6g %.6g %s %c\n", n->ratio, most_square, where, "RGB"[n->c]);
        }
        if (req->diff_path != NULL || req->diff_thumb != NULL)
            printf("heat_scale %.9g\nheat_unit z\n", d->z_critical);
        if (d->nonfinite > 0)
            printf("nonfinite %ld\n", d->nonfinite);
        printf("verdict %s\nreason %s\n", pass ? "PASS" : "FAIL", reason);
        return;
    }
    if (!req->quiet) {
        printf("statistical reference: P %d, S %d; means of %d renders (seeds %s), variances "
               "from %d; the \"%s\" standard\n",
               ref->p, ref->s, ref->mean_samples, ref->seeds, ref->variance_samples,
               standard_name(d->standard));
        printf("compared as: %s\n",
               !d->codes ? "linear values"
               : req->kind == IMGFILE_PNG
                   ? "8-bit sRGB code values (the image is a PNG), with the renders' code values"
                   : "8-bit sRGB code values, as raytra would write the image to a PNG (P = 1: "
                     "a pixel is one sample)");
        printf("exact test: %ld pixels differ where the references agree away from noise (0 "
               "allowed), %ld next to noise (fewer than %ld allowed)\n",
               d->deep, d->fringe, d->fringe_limit);
        printf("bias test: %d blocks of %d x %d pixels and the whole image, 3 channels: %d "
               "tests, Holm at %g family-wise (the worst fails beyond |z| = %.2f; %s)\n",
               d->nx * d->ny, STATDIFF_BLOCK, STATDIFF_BLOCK, d->count + 3, STATDIFF_ALPHA,
               d->z_critical,
               d->bounded ? "p-values by Bernstein's bound on the codes' range"
                          : "p-values by the normal law");
        printf("    largest |z|: %.2f at %s, %c: mean difference %+.3g %s (standard "
               "error %.3g; %.3g allowed for rounding); %d tests fail\n",
               fabs(w->z), where, "RGB"[w->c], w -> diff, d -> codes ? "codes" : "", w->se,
               allowance(d->codes, w->n > 0 ? w->sum_m / w->n : 0), d->rejected);
        printf("noise test: the residual's RMS is %.2f times the expected one over the noisy "
               "squares of %d x %d pixels (%d, a channel each; from %.2f to %.2f)",
               d->noise_image, NOISE_SPAN * STATDIFF_BLOCK, NOISE_SPAN * STATDIFF_BLOCK, d->noisy,
               STATDIFF_NOISE_LOW, most_image);
        if (n != NULL) {
            square_text(n, img->width, img->height, where, sizeof where);
            printf("; %.2f times at most in a square, at %s, %c (at most %.2f)", n->ratio, where,
                   "RGB"[n->c], most_square);
        }
        printf("\n");
        if (req->diff_path != NULL)
            printf("heat map: each block's largest |z|: black = within rounding, white = %.2f "
                   "(fails) and beyond, and the pixels compared exactly that differ; written "
                   "to %s\n",
                   d->z_critical, req->diff_path);
    }
    printf("%s: %s\n", pass ? "PASS" : "FAIL", reason);
}

/* Judges img (codes: read from a PNG) against ref by the standard, for tools that judge
 * many renders; false when out of memory. */
bool statdiff_judge(const McRef *ref, const Image *img, bool png, StatStandard standard,
                    StatVerdict *out)
{
    StatDiff d;
    bool ok = statdiff_compare(ref, img, png, standard, &d);
    if (ok) {
        char reason[512];
        *out = (StatVerdict){0};
        out->pass = verdict(&d, ref, img->width, img->height, out->test, reason, sizeof reason);
        out->z_fraction = fabs(worst_test(&d)->z) / d.z_critical;
        out->noise_image = d.noise_image;
        out->noise_block = d.noise_worst.ratio;
        out->exact_differ = (int)(d.deep + d.fringe);
    }
    free(d.tests);
    free(d.mark);
    return ok;
}

/* Judges req->image against the statistical reference req->reference (imgdiff's mode for
 * Monte Carlo renders); returns imgdiff's exit status: 0 pass, 1 fail, 2 trouble. */
int statdiff_run(const StatDiffRequest *req)
{
    McRef ref;
    Image img;
    Error err;
    if (!mcref_read(&ref, req->reference, &err)) {
        fprintf(stderr, "imgdiff: cannot read '%s': %s\n", req->reference, err.text);
        return EXIT_TROUBLE;
    }
    if (!image_read(&img, req->image, &err)) {
        fprintf(stderr, "imgdiff: cannot read '%s': %s\n", req->image, err.text);
        mcref_free(&ref);
        return EXIT_TROUBLE;
    }
    int status = EXIT_TROUBLE;
    StatDiff d = {0};
    bool png = req->kind == IMGFILE_PNG;
    if (img.width != ref.width || img.height != ref.height)
        fprintf(stderr, "imgdiff: '%s' changed while it was read\n", req->image);
    else if (req->thumb_path != NULL &&
             !imgmap_write_thumb(&img, false, png ? PNG_ENCODING_LINEAR : PNG_ENCODING_SRGB,
                                 req->thumb_path))
        status = EXIT_TROUBLE; /* reported */
    else if (!statdiff_compare(&ref, &img, png, req->standard, &d))
        fprintf(stderr, "imgdiff: out of memory\n");
    else if ((req->diff_path == NULL && req->diff_thumb == NULL) ||
             write_heat(&d, img.width, img.height, req)) {
        char reason[512], test[16];
        bool pass = verdict(&d, &ref, img.width, img.height, test, reason, sizeof reason);
        print_figures(&d, &ref, &img, req, pass, reason);
        status = pass ? EXIT_MATCH : EXIT_DIFFER;
    }
    free(d.tests);
    free(d.mark);
    image_free(&img);
    mcref_free(&ref);
    return status;
}
