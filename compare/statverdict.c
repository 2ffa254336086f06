/* statverdict.c: the verdict on a render compared by statistics, with the test that decides it. */
#include "statverdict.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "statexact.h"

/* Writes into text the block of test t, in pixels, y from the top; the whole image for
 * an image's test. */
void statverdict_block_text(const BlockTest *t, int width, int height, char *text, size_t size)
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
void statverdict_square_text(const NoiseTest *n, int width, int height, char *text, size_t size)
{
    int side = NOISE_SPAN * STATDIFF_BLOCK, x0 = n->bx * STATDIFF_BLOCK,
        y0 = n->by * STATDIFF_BLOCK;
    snprintf(text, size, "(%d,%d)-(%d,%d)", x0, y0,
             x0 + side - 1 < width ? x0 + side - 1 : width - 1,
             y0 + side - 1 < height ? y0 + side - 1 : height - 1);
}

/* Returns the most biased test: the block test of largest |z|, or a whole image's test
 * when one is rejected and no block's is. */
const BlockTest *statverdict_worst(const StatDiff *d)
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
bool statverdict_decide(const StatDiff *d, const McRef *ref, int width, int height, char *test,
                        char *text, size_t size)
{
    const BlockTest *w = statverdict_worst(d);
    char where[64];
    statverdict_block_text(w, width, height, where, sizeof where);
    const char *unit = d->codes ? "codes" : "(linear)";
    double most_image, most_square;
    statnoise_bounds(d->standard, &most_image, &most_square);
    const NoiseTest *n = d->noise.worst.ratio >= 0 ? &d->noise.worst : NULL;
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
        /* The references' variance is the standard's: an image noisier than it allows,
         * biased or not, differs beyond chance; say so, for an unbiased one. */
        size_t used = strlen(text);
        if (n != NULL && d->noise.ratio > most_image && used < size)
            snprintf(text + used, size - used,
                     "; the image is also %.2f times as noisy as raytra's, more than the \"%s\" "
                     "standard allows (%.2f), and an unbiased render that noisy fails here too",
                     d->noise.ratio, statstandard_name(d->standard), most_image);
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
    } else if (n != NULL && d->noise.ratio < STATDIFF_NOISE_LOW) {
        strcpy(test, "smooth");
        snprintf(text, size,
                 "smooth: too little noise for P %d S %d: %.2f times raytra's over the image's "
                 "noisy squares (at least %.2f): neighbouring pixels err alike, as when every "
                 "pixel takes the same random offsets (its own numbers not drawn for each "
                 "pixel); or more samples than asked, a denoiser, an average of renders?",
                 ref->p, ref->s, d->noise.ratio, STATDIFF_NOISE_LOW);
    } else if (n != NULL && d->noise.ratio > most_image) {
        strcpy(test, "noise");
        snprintf(text, size,
                 "noise: unbiased, but %.2f times as noisy as raytra's at P %d S %d over the "
                 "image's noisy squares, more than the \"%s\" standard allows (%.2f): fewer "
                 "samples than asked, a pixel's samples spread beyond it (a filter wider than "
                 "the pixel), or %s?",
                 d->noise.ratio, ref->p, ref->s, statstandard_name(d->standard), most_image,
                 d->standard == STATDIFF_OK
                     ? "a pixel's samples not stratified"
                     : "a pixel's samples, or an area light's if the scene has one, not stratified");
    } else if (n != NULL && n->ratio > most_square) {
        strcpy(test, "noise");
        statverdict_square_text(n, width, height, where, sizeof where);
        snprintf(text, size,
                 "noise: unbiased, but the square %s, %c, is %.2f times as noisy as raytra's at "
                 "P %d S %d, more than the \"%s\" standard allows (%.2f): a pixel's samples "
                 "spread beyond it (a filter wider than the pixel), or %s?",
                 where, "RGB"[n->c], n -> ratio, ref -> p, ref -> s,
                 statstandard_name(d->standard), most_square,
                 d -> standard == STATDIFF_OK
                     ? "a pixel's samples not stratified"
                     : "a pixel's samples, or an area light's if the scene has one, not stratified");
    } else {
        snprintf(text, size,
                 "converges to the reference: no block biased (largest |z| %.2f, critical %.2f), "
                 "noise %.2f times the expected (\"%s\" standard)",
                 fabs(w->z), d->z_critical, d->noise.ratio, statstandard_name(d->standard));
        return true;
    }
    return false;
}
