/* statexact.c: the exact test of the pixels that every render of the reference saw alike. */
#include "statexact.h"

#include <math.h>
#include <stdlib.h>

/* A pixel the references saw without noise is on the fringe of the noise when a pixel with
 * noise lies within FRINGE pixels of it (across or down): it may be one that varies
 * rarely, such as a penumbra's last pixel, lit by one render in a hundred. */
#define FRINGE 4
/* The chance that a pixel's 64 references agree and one more render differs: at most
 * max over q of q (1 - q)^64 = (1/65) (64/65)^64, whatever the chance q that it differs
 * (Good and Turing's missing mass: the render is the 65th of 65 alike). */
#define UNSEEN_CHANCE 0.005673

/* Returns how far a value may be from the value m that every reference had and still be
 * the same: one code (rounding the other way, or truncation); linear, a half float's
 * rounding doubled, 2^-10 (|m| + 1/64). */
double statexact_tolerance(bool codes, double m)
{
    return codes ? 1.001 : ldexp(fabs(m) + 1.0 / 64, -10);
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

/* Marks in noisy the pixels whose reference varies in some channel, and sets in near the
 * count of such pixels within FRINGE of each pixel (a summed-area table). */
bool statexact_near_noise(const McRef *ref, bool codes, int *near)
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

/* Returns the fewest differing pixels on the fringe of the noise that fail the exact test:
 * the fewest whose chance is below its error rate, when each of fringe_channels channels
 * differs at most UNSEEN_CHANCE. */
long statexact_fringe_limit(long fringe_channels)
{
    double mu = UNSEEN_CHANCE * fringe_channels;
    long limit = (long)mu + 1;
    while (chernoff_tail(limit, mu) > STATDIFF_ALPHA_EXACT)
        limit++;
    return limit;
}
