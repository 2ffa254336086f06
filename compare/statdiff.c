/* statdiff.c: a render judged against a statistical reference; imgdiff's figures and heat map. */
#include "statdiff.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "image_read.h"
#include "imgmap.h"
#include "statcompare.h"
#include "statverdict.h"

enum { EXIT_MATCH = 0, EXIT_DIFFER = 1, EXIT_TROUBLE = 2 };

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
    const BlockTest *w = statverdict_worst(d);
    const NoiseTest *n = d->noise.worst.ratio >= 0 ? &d->noise.worst : NULL;
    double most_image, most_square;
    statnoise_bounds(d->standard, &most_image, &most_square);
    char where[64];
    statverdict_block_text(w, img->width, img->height, where, sizeof where);
    if (req->machine) {
        printf("mode statistics\nstandard %s\nsize %d %d\nmax %.9g %.9g %.9g\nmean %.9g\n"
               "rmse %.9g\npsnr %.9g\ndiffering %ld %ld\n",
               statstandard_name(d->standard), img->width, img->height, d->max[0], d->max[1],
               d->max[2], mean, rmse, -20 * log10(rmse), differing, pixels);
        if (differing > 0)
            printf("box %d %d %d %d\n", box[0], box[1], box[2], box[3]);
        printf("exact %ld %ld %ld\n", d->deep, d->fringe, d->fringe_limit);
        printf("bias_tests %d %d\nbias_worst %.6g %.6g %s %c\nnoise_image %.6g %.6g %.6g\n",
               d->rejected, d->count + 3, w->z, d->z_critical, where, "RGB"[w->c], d->noise.ratio,
               STATDIFF_NOISE_LOW, most_image);
        if (n != NULL) {
            statverdict_square_text(n, img->width, img->height, where, sizeof where);
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
               statstandard_name(d->standard));
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
                          : "p-values by Student's t law, as normal z-scores");
        printf("    largest |z|: %.2f at %s, %c: mean difference %+.3g %s (standard "
               "error %.3g; %.3g allowed for quantisation); %d tests fail\n",
               fabs(w->z), where, "RGB"[w->c], w -> diff, d -> codes ? "codes" : "", w->se,
               statbias_allowance(d->codes, w->n > 0 ? w->sum_m / w->n : 0), d->rejected);
        printf("noise test: the residual's RMS is %.2f times the expected one over the noisy "
               "squares of %d x %d pixels (%d, a channel each; from %.2f to %.2f)",
               d->noise.ratio, NOISE_SPAN * STATDIFF_BLOCK, NOISE_SPAN * STATDIFF_BLOCK,
               d->noise.noisy, STATDIFF_NOISE_LOW, most_image);
        if (n != NULL) {
            statverdict_square_text(n, img->width, img->height, where, sizeof where);
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
    bool ok = statcompare_image(ref, img, png, standard, &d);
    if (ok) {
        char reason[512];
        *out = (StatVerdict){0};
        out->pass =
            statverdict_decide(&d, ref, img->width, img->height, out->test, reason, sizeof reason);
        out->z_fraction = fabs(statverdict_worst(&d)->z) / d.z_critical;
        out->noise_image = d.noise.ratio;
        out->noise_block = d.noise.worst.ratio;
        out->exact_differ = (int)(d.deep + d.fringe);
    }
    statcompare_free(&d);
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
    else if (!statcompare_image(&ref, &img, png, req->standard, &d))
        fprintf(stderr, "imgdiff: out of memory\n");
    else if ((req->diff_path == NULL && req->diff_thumb == NULL) ||
             write_heat(&d, img.width, img.height, req)) {
        char reason[512], test[16];
        bool pass =
            statverdict_decide(&d, &ref, img.width, img.height, test, reason, sizeof reason);
        print_figures(&d, &ref, &img, req, pass, reason);
        status = pass ? EXIT_MATCH : EXIT_DIFFER;
    }
    statcompare_free(&d);
    image_free(&img);
    mcref_free(&ref);
    return status;
}
