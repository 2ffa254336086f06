/* statnoise.c: the noise test: is a render as noisy as raytra's at its P and S, in each square? */
#include "statnoise.h"

#include <math.h>

/* The noise test of channel c of the square of blocks from (bx, by), whose sums it adds to
 * the image's when it tells: the residual's RMS about each block's mean difference over the
 * expected one (a bias, or a PNG written by truncation, is not noise), or -1 when the square
 * has too little noise to tell: noise below the floors, or on fewer than NOISE_PIXELS pixels
 * in effect ((sum v)^2 / sum v^2). A block's squared residuals are winsorised at NOISE_CAP
 * standard deviations on the whole: one rare bright sample (a highlight) cannot make a
 * square noisy. */
static NoiseTest test_square(const BlockTest *tests, int nx, int ny, int bx, int by, int c,
                             ImageNoise *image)
{
    double r2 = 0, v = 0, floors = 0, noise = 0, noise2 = 0;
    for (int y = by; y < by + NOISE_SPAN && y < ny; y++)
        for (int x = bx; x < bx + NOISE_SPAN && x < nx; x++) {
            const BlockTest *t = &tests[3 * (y * nx + x) + c];
            double spread = t->n > 0 ? t->sum_d2 - t->sum_d * t->sum_d / t->n : 0;
            r2 += fmin(spread, NOISE_CAP * NOISE_CAP * t->sum_v), v += t->sum_v;
            floors += t->floors, noise += t->noise, noise2 += t->noise2;
        }
    NoiseTest n = {.bx = bx, .by = by, .c = c, .ratio = -1};
    if (noise > floors && noise * noise >= NOISE_PIXELS * noise2) {
        n.ratio = sqrt(r2 / v);
        image->noisy++;
        image->r2 += r2, image->v += v;
    }
    return n;
}

/* Makes the noise test of each channel of each square of an image of nx x ny blocks, whose
 * tests (three a block) hold their sums: the noisiest square, and the ratio over them all. */
void statnoise_image(const BlockTest *tests, int nx, int ny, ImageNoise *noise)
{
    *noise = (ImageNoise){.worst = {.ratio = -1}};
    for (int by = 0; by < ny; by += NOISE_SPAN)
        for (int bx = 0; bx < nx; bx += NOISE_SPAN)
            for (int c = 0; c < 3; c++) {
                NoiseTest n = test_square(tests, nx, ny, bx, by, c, noise);
                if (n.ratio > noise->worst.ratio)
                    noise->worst = n;
            }
    noise->ratio = noise->v > 0 ? sqrt(noise->r2 / noise->v) : 0;
}

/* Returns the standard's bounds on the noise ratio, over the image and in a square. */
void statnoise_bounds(StatStandard standard, double *image, double *square)
{
    *image = standard == STATDIFF_OK ? STATDIFF_OK_IMAGE : STATDIFF_GOOD_IMAGE;
    *square = standard == STATDIFF_OK ? STATDIFF_OK_BLOCK : STATDIFF_GOOD_BLOCK;
}
