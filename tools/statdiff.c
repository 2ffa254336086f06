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

/* The test of one channel of one block. */
typedef struct {
    int bx, by, c; /* the block's column and row of blocks, the channel */
    double diff;   /* the mean difference, image minus reference */
    double se;     /* its standard error */
    double z, p;   /* the z-score beyond the rounding allowance, its two-sided p-value */
    bool rejected; /* biased, by Holm's procedure */
    /* The noise test's sums over the block: squared residuals, expected variances with
     * their floors, the floors, and the reference's variances and their squares. */
    double sum_r2, sum_v, floors, noise, noise2;
} BlockTest;

/* The noise test of one channel of a square of NOISE_SPAN x NOISE_SPAN blocks. */
typedef struct {
    int bx, by, c; /* its first block, the channel */
    double ratio;  /* the residual's RMS over the expected one */
} NoiseTest;

/* The comparison of a whole image. */
typedef struct {
    bool codes;        /* compared as 8-bit code values (the image is a PNG) */
    int nx, ny, count; /* blocks across and down; tests (blocks x channels) */
    BlockTest *tests;
    int rejected, worst;      /* tests found biased; the test of largest |z| */
    double z_critical;        /* the |z| beyond which the worst test is rejected */
    double noise_image;       /* the residual's RMS over the expected one, noisy squares */
    int noisy;                /* noise tests made: squares with noise enough */
    NoiseTest noise_worst;    /* the one of largest ratio (ratio -1 when none) */
    double noise_r2, noise_v; /* the noise tests' sums */
    double max[3], sum, sum2; /* raw differences, on a 0 to 1 scale, for the figures */
    long nonfinite;
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
 * difference no test counts, one code, or 2^-10 (1 + |m|) linear. */
static double allowance(bool codes, double m)
{
    return codes ? 1.0 : ldexp(1 + fabs(m), -10);
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

/* Orders tests by p-value, smallest first (Holm's order). */
static int by_p(const void *a, const void *b)
{
    double p = (*(const BlockTest *const *)a)->p, q = (*(const BlockTest *const *)b)->p;
    return (p > q) - (p < q);
}

/* Tests one channel c of block (bx, by) of img against ref: the bias z-test and the noise
 * ratio. */
static BlockTest test_block(const McRef *ref, const Image *img, bool codes, int bx, int by, int c,
                            StatDiff *d)
{
    const float *mean = ref->plane[codes ? MCREF_CODE : MCREF_MEAN];
    const float *var = ref->plane[codes ? MCREF_CODE_VAR : MCREF_VAR];
    double inflate = 1 + 1.0 / ref->mean_samples; /* the reference's mean is noisy too */
    double sum_d = 0, sum_v = 0, sum_m = 0, sum_r2 = 0, noise = 0, noise2 = 0, floors = 0;
    int n = 0;
    for (int y = by * STATDIFF_BLOCK; y < (by + 1) * STATDIFF_BLOCK && y < img->height; y++)
        for (int x = bx * STATDIFF_BLOCK; x < (bx + 1) * STATDIFF_BLOCK && x < img->width;
             x++, n++) {
            long k = 3 * ((long)y * img->width + x) + c;
            double s = img->pixels[k] * (codes ? 255.0 : 1.0), m = mean[k];
            double v = fmax(var[k], 0) * inflate, q = floor_variance(codes, m), r = s - m;
            if (!isfinite(s)) {
                d->nonfinite++;
                r = 0;
            }
            double raw = fabs(r) / (codes ? 255.0 : 1.0);
            d->max[c] = fmax(d->max[c], raw);
            d->sum += raw, d->sum2 += raw * raw;
            /* Winsorised at NOISE_CAP standard deviations: a pixel's rare bright sample
             * (a highlight) counts as a big residual, not as the whole square's noise. */
            sum_d += r, sum_m += m, sum_r2 += fmin(r * r, NOISE_CAP * NOISE_CAP * (v + q));
            sum_v += v + q, floors += q, noise += v, noise2 += v * v;
        }
    BlockTest t = {.bx = bx,
                   .by = by,
                   .c = c,
                   .diff = sum_d / n,
                   .se = sqrt(sum_v) / n,
                   .sum_r2 = sum_r2,
                   .sum_v = sum_v,
                   .floors = floors,
                   .noise = noise,
                   .noise2 = noise2};
    double excess = fmax(0, fabs(t.diff) - allowance(codes, sum_m / n));
    t.z = copysign(excess / t.se, t.diff);
    t.p = erfc(fabs(t.z) / sqrt(2));
    return t;
}

/* The noise test of channel c of the square of blocks from (bx, by): the residual's RMS
 * over the expected one, or -1 when the square has too little noise to tell: noise below
 * the floors, or on fewer than NOISE_PIXELS pixels in effect ((sum v)^2 / sum v^2). */
static NoiseTest test_noise(StatDiff *d, int bx, int by, int c)
{
    double r2 = 0, v = 0, floors = 0, noise = 0, noise2 = 0;
    for (int y = by; y < by + NOISE_SPAN && y < d->ny; y++)
        for (int x = bx; x < bx + NOISE_SPAN && x < d->nx; x++) {
            const BlockTest *t = &d->tests[3 * (y * d->nx + x) + c];
            r2 += t->sum_r2, v += t->sum_v, floors += t->floors;
            noise += t->noise, noise2 += t->noise2;
        }
    NoiseTest n = {.bx = bx, .by = by, .c = c, .ratio = -1};
    if (noise > floors && noise * noise >= NOISE_PIXELS * noise2) {
        n.ratio = sqrt(r2 / v);
        d->noisy++;
        d->noise_r2 += r2, d->noise_v += v;
    }
    return n;
}

/* Compares img with ref block by block: bias z-tests corrected by Holm's procedure, noise
 * ratios; false when out of memory. */
static bool statdiff_compare(const McRef *ref, const Image *img, bool codes, StatDiff *d)
{
    *d = (StatDiff){.codes = codes, .noise_worst = {.ratio = -1}};
    d->nx = (img->width + STATDIFF_BLOCK - 1) / STATDIFF_BLOCK;
    d->ny = (img->height + STATDIFF_BLOCK - 1) / STATDIFF_BLOCK;
    d->count = 3 * d->nx * d->ny;
    d->tests = calloc((size_t)d->count, sizeof *d->tests);
    BlockTest **order = calloc((size_t)d->count, sizeof *order);
    if (d->tests == NULL || order == NULL) {
        free(order);
        return false;
    }
    for (int by = 0, k = 0; by < d->ny; by++)
        for (int bx = 0; bx < d->nx; bx++)
            for (int c = 0; c < 3; c++, k++) {
                BlockTest *t = &d->tests[k];
                *t = test_block(ref, img, codes, bx, by, c, d);
                order[k] = t;
                if (fabs(t->z) > fabs(d->tests[d->worst].z))
                    d->worst = k;
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
    qsort(order, (size_t)d->count, sizeof *order, by_p);
    for (int j = 0; j < d->count && order[j]->p <= STATDIFF_ALPHA / (d->count - j); j++)
        order[j]->rejected = true, d->rejected++;
    d->z_critical = z_of_p(STATDIFF_ALPHA / d->count);
    free(order);
    return true;
}

/* Writes the heat map of d: each block the colour of its largest |z| over its channels,
 * white at the critical value and beyond; black within the rounding allowance. */
static bool write_heat(const StatDiff *d, int width, int height, const StatDiffRequest *req)
{
    float *level = malloc((size_t)width * height * sizeof *level);
    if (level == NULL)
        return false;
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            const BlockTest *t = &d->tests[3 * ((y / STATDIFF_BLOCK) * d->nx + x / STATDIFF_BLOCK)];
            level[(long)y * width + x] =
                (float)fmax(fabs(t[0].z), fmax(fabs(t[1].z), fabs(t[2].z)));
        }
    bool ok =
        imgmap_write_levels(level, width, height, d->z_critical, req->diff_path, req->diff_thumb);
    free(level);
    return ok;
}

/* Writes into text the block of test t, in pixels, y from the top. */
static void block_text(const BlockTest *t, int width, int height, char *text, size_t size)
{
    int x0 = t->bx * STATDIFF_BLOCK, y0 = t->by * STATDIFF_BLOCK;
    int x1 = x0 + STATDIFF_BLOCK - 1 < width ? x0 + STATDIFF_BLOCK - 1 : width - 1;
    int y1 = y0 + STATDIFF_BLOCK - 1 < height ? y0 + STATDIFF_BLOCK - 1 : height - 1;
    snprintf(text, size, "(%d,%d)-(%d,%d)", x0, y0, x1, y1);
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

/* Writes the verdict's reason into text; returns whether the image passes. */
static bool verdict(const StatDiff *d, const McRef *ref, int width, int height, char *text,
                    size_t size)
{
    const BlockTest *w = &d->tests[d->worst];
    char where[64];
    block_text(w, width, height, where, sizeof where);
    const char *unit = d->codes ? "codes" : "(linear)";
    if (d->nonfinite > 0) {
        snprintf(text, size, "%ld pixel values are not finite (NaN or infinite)", d->nonfinite);
        return false;
    }
    if (d->rejected > 0) {
        snprintf(text, size,
                 "bias: %d of %d block tests differ from the reference beyond chance "
                 "(family-wise 0.001); the worst, block %s, %c: %s by %.3g %s, z = %.1f",
                 d->rejected, d->count, where, "RGB"[w->c], w -> diff > 0 ? "brighter" : "darker",
                 fabs(w->diff), unit, w->z);
        return false;
    }
    const NoiseTest *n = d->noise_worst.ratio >= 0 ? &d->noise_worst : NULL;
    if (n != NULL && d->noise_image > STATDIFF_NOISE_IMAGE) {
        snprintf(text, size,
                 "noise: the residual is %.2f times as noisy as raytra's at P %d S %d over the "
                 "image's noisy blocks (at most %.2f allowed): fewer samples, or not stratified?",
                 d->noise_image, ref->p, ref->s, STATDIFF_NOISE_IMAGE);
        return false;
    }
    if (n != NULL && n->ratio > STATDIFF_NOISE_BLOCK) {
        square_text(n, width, height, where, sizeof where);
        snprintf(text, size,
                 "noise: the square %s, %c, is %.2f times as noisy as raytra's at P %d S %d "
                 "(at most %.2f allowed): not stratified, or fewer samples?",
                 where, "RGB"[n->c], n -> ratio, ref -> p, ref -> s, STATDIFF_NOISE_BLOCK);
        return false;
    }
    snprintf(text, size,
             "converges to the reference: no block biased (largest |z| %.2f, critical %.2f), "
             "noise %.2f times the expected",
             fabs(w->z), d->z_critical, d->noise_image);
    return true;
}

/* Returns how many pixels of a block starting at x0 lie within an image extent wide. */
static int box_side(int x0, int extent)
{
    return x0 + STATDIFF_BLOCK <= extent ? STATDIFF_BLOCK : extent - x0;
}

/* Prints the figures of d, in words or with --machine as NAME VALUE lines. */
static void print_figures(const StatDiff *d, const McRef *ref, const Image *img,
                          const StatDiffRequest *req, bool pass, const char *reason)
{
    long pixels = (long)img->width * img->height, in_rejected = 0;
    int box[4] = {img->width, img->height, -1, -1};
    for (int k = 0; k < d->count; k += 3)
        if (d->tests[k].rejected || d->tests[k + 1].rejected || d->tests[k + 2].rejected) {
            const BlockTest *t = &d->tests[k];
            int x0 = t->bx * STATDIFF_BLOCK, y0 = t->by * STATDIFF_BLOCK;
            box[0] = x0 < box[0] ? x0 : box[0], box[1] = y0 < box[1] ? y0 : box[1];
            int x1 = x0 + STATDIFF_BLOCK - 1, y1 = y0 + STATDIFF_BLOCK - 1;
            box[2] = x1 > box[2] ? (x1 < img->width ? x1 : img->width - 1) : box[2];
            box[3] = y1 > box[3] ? (y1 < img->height ? y1 : img->height - 1) : box[3];
            in_rejected += (long)(box_side(x0, img->width) * box_side(y0, img->height));
        }
    double mean = d->sum / (3.0 * pixels), rmse = sqrt(d->sum2 / (3.0 * pixels));
    const BlockTest *w = &d->tests[d->worst];
    const NoiseTest *n = d->noise_worst.ratio >= 0 ? &d->noise_worst : NULL;
    char where[64];
    block_text(w, img->width, img->height, where, sizeof where);
    if (req->machine) {
        printf("mode statistics\nsize %d %d\nmax %.9g %.9g %.9g\nmean %.9g\nrmse %.9g\n"
               "psnr %.9g\ndiffering %ld %ld\n",
               img->width, img->height, d->max[0], d->max[1], d->max[2], mean, rmse,
               -20 * log10(rmse), in_rejected, pixels);
        if (in_rejected > 0)
            printf("box %d %d %d %d\n", box[0], box[1], box[2], box[3]);
        printf("bias_tests %d %d\nbias_worst %.6g %.6g %s %c\nnoise_image %.6g %.6g\n", d->rejected,
               d->count, w->z, d->z_critical, where, "RGB"[w->c], d -> noise_image,
               STATDIFF_NOISE_IMAGE);
        if (n != NULL) {
            square_text(n, img->width, img->height, where, sizeof where);
            printf("noise_block %.6g %.6g %s %c\n", n->ratio, STATDIFF_NOISE_BLOCK, where,
                   "RGB"[n->c]);
        }
        if (req->diff_path != NULL || req->diff_thumb != NULL)
            printf("heat_scale %.9g\n", d->z_critical);
        if (d->nonfinite > 0)
            printf("nonfinite %ld\n", d->nonfinite);
        printf("verdict %s\nreason %s\n", pass ? "PASS" : "FAIL", reason);
        return;
    }
    if (!req->quiet) {
        printf("statistical reference: P %d, S %d; means of %d renders (seeds %s), variances "
               "from %d\n",
               ref->p, ref->s, ref->mean_samples, ref->seeds, ref->variance_samples);
        printf("compared as: %s\n", d->codes ? "8-bit sRGB code values (the image is a PNG), "
                                               "with the renders' code values"
                                             : "linear values");
        printf("bias test: %d blocks of %d x %d pixels, 3 channels: %d z-tests, Holm at %g "
               "family-wise (the worst block fails beyond |z| = %.2f)\n",
               d->nx * d->ny, STATDIFF_BLOCK, STATDIFF_BLOCK, d->count, STATDIFF_ALPHA,
               d->z_critical);
        printf("    largest |z|: %.2f at block %s, %c: mean difference %+.3g %s (standard "
               "error %.3g; %.3g allowed for rounding); %d tests fail\n",
               fabs(w->z), where, "RGB"[w->c], w -> diff, d -> codes ? "codes" : "", w->se,
               allowance(d->codes, 0), d->rejected);
        printf("noise test: the residual's RMS is %.2f times the expected one over the noisy "
               "squares of %d x %d pixels (%d, a channel each; at most %.2f)",
               d->noise_image, NOISE_SPAN * STATDIFF_BLOCK, NOISE_SPAN * STATDIFF_BLOCK, d->noisy,
               STATDIFF_NOISE_IMAGE);
        if (n != NULL) {
            square_text(n, img->width, img->height, where, sizeof where);
            printf("; %.2f times at most in a square, at %s, %c (at most %.2f)", n->ratio, where,
                   "RGB"[n->c], STATDIFF_NOISE_BLOCK);
        }
        printf("\n");
        if (req->diff_path != NULL)
            printf("heat map: each block's largest |z|: black = within rounding, white = %.2f "
                   "(fails) and beyond, written to %s\n",
                   d->z_critical, req->diff_path);
    }
    printf("%s: %s\n", pass ? "PASS" : "FAIL", reason);
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
    bool codes = req->kind == IMGFILE_PNG;
    if (img.width != ref.width || img.height != ref.height)
        fprintf(stderr, "imgdiff: '%s' changed while it was read\n", req->image);
    else if (req->thumb_path != NULL &&
             !imgmap_write_thumb(&img, false, codes ? PNG_ENCODING_LINEAR : PNG_ENCODING_SRGB,
                                 req->thumb_path))
        status = EXIT_TROUBLE; /* reported */
    else if (!statdiff_compare(&ref, &img, codes, &d))
        fprintf(stderr, "imgdiff: out of memory\n");
    else if ((req->diff_path == NULL && req->diff_thumb == NULL) ||
             write_heat(&d, img.width, img.height, req)) {
        char reason[512];
        bool pass = verdict(&d, &ref, img.width, img.height, reason, sizeof reason);
        print_figures(&d, &ref, &img, req, pass, reason);
        status = pass ? EXIT_MATCH : EXIT_DIFFER;
    }
    free(d.tests);
    image_free(&img);
    mcref_free(&ref);
    return status;
}
