/* statbias.c: the bias test of a block: is its mean difference from the reference beyond chance? */
#include "statbias.h"

#include <math.h>
#include <stdlib.h>

#include "statt.h"

/* Returns the variance floor of a pixel whose reference value is m: in codes, a uniform
 * rounding error, 1/12 code^2; linear, the rounding of a half-float file (2^-11 relative,
 * doubled for safety), (2^-10 (|m| + 1/64))^2 / 12. */
double statbias_floor_variance(bool codes, double m)
{
    double step = ldexp(fabs(m) + 1.0 / 64, -10);
    return codes ? 1.0 / 12 : step * step / 12;
}

/* Returns the rounding allowance of a block whose reference mean is m: the systematic
 * difference the file's quantisation may make and no test counts. In codes, half a code:
 * the references' code values are rounded, and a writer that rounds otherwise (such as
 * truncation) moves a noisy pixel's mean by half a code; linear, one unit in the last place
 * of a half float, 2^-10 |m| (an EXR rounded either way; a PFM's floats are closer still). */
double statbias_allowance(bool codes, double m)
{
    return codes ? 0.5 : ldexp(fabs(m), -10);
}

/* Returns Bernstein's bound on the chance that a sum of independent deviations of total
 * variance v, each at most b, reaches t: exp(-t^2 / (2 (v + b t / 3))). */
static double bernstein(double t, double v, double b)
{
    return t <= 0 ? 1 : exp(-t * t / (2 * (v + b * t / 3)));
}

/* Orders tests by p-value, smallest first (Holm's order). */
static int by_p(const void *a, const void *b)
{
    double p = (*(const BlockTest *const *)a)->p, q = (*(const BlockTest *const *)b)->p;
    return (p > q) - (p < q);
}

/* Adds pixel-channel k's difference from the reference to the sums of test t: its value
 * s, the reference's mean m and variance v of one render, the space's floor q. */
void statbias_add(BlockTest *t, bool codes, double s, double m, double v, double q)
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
 * its standard error, and its two-sided p-value. By the "good" standard the variance is
 * the references' alone (with the floors): the block's own differences never widen it, so
 * that an error that varies inside the block (an edge moved or blurred) is not taken for
 * noise. Their variances are estimates of pixel_df degrees of freedom each: the ratio is
 * Student's t of Satterthwaite's degrees of freedom for their sum, and its p-value the t
 * law's tail. By the "ok" standard (own), whose random points on the light make noise the
 * references do not show, the variance is the larger of theirs and the one the image's
 * differences show (n / (n - 1) times their sum of squares about their mean), of n - 1
 * degrees of freedom. At P = 1 (bounded), Bernstein's inequality over the range of a code
 * value. */
void statbias_finish(BlockTest *t, bool codes, bool bounded, double pixel_df, bool own)
{
    if (t->n == 0) {
        t->p = 1;
        return;
    }
    t->diff = t->sum_d / t->n;
    /* Satterthwaite: the sum of the variances, of which the floors are known, has
     * pixel_df (sum v)^2 / sum v_i^2 degrees of freedom. */
    double v = t->sum_v, df = t->noise2 > 0 ? pixel_df * v * v / t->noise2 : INFINITY;
    double spread = t->n > 1 ? (t->sum_d2 - t->sum_d * t->diff) * t->n / (t->n - 1) : 0;
    if (own && spread > v)
        v = spread, df = t->n - 1;
    t->se = sqrt(v) / t->n;
    double excess = fmax(0, fabs(t->diff) - statbias_allowance(codes, t->sum_m / t->n));
    if (bounded) {
        double tail = excess * t->n;
        t->p = fmin(1, bernstein(tail, v, t->up) + bernstein(tail, v, t->down));
    } else
        t->p = t->se > 0 ? statt_two_sided(excess / t->se, df) : 1;
    t->z = copysign(t->p < 1 ? statt_normal_z(t->p) : 0, t->diff);
}

/* Rejects the biased among the count tests of order (which it sorts by p-value) at the
 * family-wise error rate STATDIFF_ALPHA; returns how many it rejects. */
int statbias_holm(BlockTest **order, int count)
{
    /* Holm: the j-th smallest p-value (from 0) is rejected when it and all before it are
     * at most alpha / (count - j); the family-wise error rate is then at most alpha. */
    qsort(order, (size_t)count, sizeof *order, by_p);
    int rejected = 0;
    for (int j = 0; j < count && order[j]->p <= STATDIFF_ALPHA / (count - j); j++)
        order[j]->rejected = true, rejected++;
    return rejected;
}

/* Returns the |z| beyond which the worst of count tests is rejected: Holm's first bound,
 * alpha / count, as a z-score. */
double statbias_critical(int count)
{
    return statt_normal_z(STATDIFF_ALPHA / count);
}
