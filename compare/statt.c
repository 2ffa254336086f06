/* statt.c: Student's t law and the normal law's tails, for the bias test's p-values. */
#include "statt.h"

#include <float.h>
#include <math.h>

/* Returns the continued fraction of the regularised incomplete beta function I_x(a, b),
 * by Lentz's method (Abramowitz and Stegun 26.5.8); it converges fast for
 * x < (a + 1) / (a + b + 2). */
static double beta_fraction(double a, double b, double x)
{
    const double tiny = 1e-300;
    double c = 1, d = 1 - (a + b) * x / (a + 1);
    d = 1 / (fabs(d) < tiny ? tiny : d);
    double f = d;
    for (int m = 1; m <= 10000; m++) {
        /* The even step d_2m, then the odd step d_2m+1. */
        for (int odd = 0; odd < 2; odd++) {
            double num = odd ? -(a + m) * (a + b + m) * x / ((a + 2 * m) * (a + 2 * m + 1))
                             : m * (b - m) * x / ((a + 2 * m - 1) * (a + 2 * m));
            d = 1 + num * d;
            d = 1 / (fabs(d) < tiny ? tiny : d);
            c = 1 + num / c;
            c = fabs(c) < tiny ? tiny : c;
            f *= c * d;
            if (odd && fabs(c * d - 1) < 4 * DBL_EPSILON)
                return f;
        }
    }
    return f;
}

/* Returns the regularised incomplete beta function I_x(a, b), for x in [0, 1]. */
static double incomplete_beta(double a, double b, double x)
{
    if (x <= 0)
        return 0;
    if (x >= 1)
        return 1;
    double front = exp(a * log(x) + b * log1p(-x) + lgamma(a + b) - lgamma(a) - lgamma(b));
    if (x < (a + 1) / (a + b + 2))
        return front * beta_fraction(a, b, x) / a;
    return 1 - front * beta_fraction(b, a, 1 - x) / b;
}

/* Returns the two-sided p-value of t under Student's t law of df degrees of freedom:
 * P(|T| >= |t|) = I_{df / (df + t^2)}(df / 2, 1 / 2); the normal law's when df is
 * infinite. Unbounded in t: the tail is computed, not approximated by a normal z. */
double statt_two_sided(double t, double df)
{
    if (isnan(t))
        return 1;
    if (isinf(df))
        return erfc(fabs(t) / sqrt(2));
    if (isinf(t))
        return 0;
    return incomplete_beta(df / 2, 0.5, df / (df + t * t));
}

/* Returns the |z| whose two-sided p-value under the normal law is p: its quantile, by
 * bisection (38.5 at most, where erfc leaves the doubles). */
double statt_normal_z(double p)
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
