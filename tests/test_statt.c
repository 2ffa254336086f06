/* test_statt.c: Student's t law of the statistical grading, on tabulated and closed-form values. */
#include <math.h>

#include "statt.h"
#include "testing.h"

/* Tabulated quantiles (any table of Student's t, such as Abramowitz and Stegun's 26.10):
 * the two-sided p-value at the quantile is twice the upper tail. */
START_TEST(tabulated_quantiles)
{
    ck_assert_double_eq_tol(statt_two_sided(2.228, 10), 0.05, 1e-4);   /* t_0.975,10 */
    ck_assert_double_eq_tol(statt_two_sided(5.893, 5), 0.002, 1e-5);   /* t_0.999,5 */
    ck_assert_double_eq_tol(statt_two_sided(2.660, 60), 0.01, 1e-4);   /* t_0.995,60 */
    ck_assert_double_eq_tol(statt_two_sided(-3.460, 60), 0.001, 1e-5); /* t_0.9995,60 */
    ck_assert_double_eq_tol(statt_two_sided(12.706, 1), 0.05, 1e-5);   /* t_0.975,1 */
}
END_TEST

/* The laws of one and two degrees of freedom have closed forms: Cauchy's, P(|T| >= t) =
 * 1 - 2 atan(t) / pi; and 1 - t / sqrt(2 + t^2). */
START_TEST(closed_forms)
{
    double ts[] = {0, 0.3, 1, 2.5, 10, 1000};
    for (int k = 0; k < 6; k++) {
        double t = ts[k];
        ck_assert_double_eq_tol(statt_two_sided(t, 1), 1 - 2 * atan(t) / acos(-1.0), 1e-12);
        ck_assert_double_eq_tol(statt_two_sided(t, 2), 1 - t / sqrt(2 + t * t), 1e-12);
    }
}
END_TEST

/* Many degrees of freedom give the normal law, and the normal quantile inverts it. */
START_TEST(normal_limit)
{
    ck_assert_double_eq_tol(statt_two_sided(1.959964, INFINITY), 0.05, 1e-7);
    ck_assert_double_eq_tol(statt_two_sided(1.959964, 1e8), 0.05, 1e-7);
    ck_assert_double_eq_tol(statt_normal_z(0.05), 1.959964, 1e-6);
    ck_assert_double_eq_tol(statt_normal_z(1e-6), 4.891638, 1e-5);
    ck_assert_double_eq_tol(statt_normal_z(erfc(12 / sqrt(2))), 12, 1e-9);
}
END_TEST

/* The tail is the t law's own, unbounded: a t of 40 on 63 degrees of freedom is far
 * beyond any normal z that an approximation bounded by sqrt(2 df) could give (11.2). */
START_TEST(unbounded)
{
    double p = statt_two_sided(40, 63);
    ck_assert(p > 0 && p < 1e-40);
    ck_assert(statt_normal_z(p) > 14);
    /* Monotone: a larger t, a smaller p; heavier tails than the normal law's. */
    ck_assert(statt_two_sided(6, 63) > statt_two_sided(7, 63));
    ck_assert(statt_two_sided(6, 63) > erfc(6 / sqrt(2)));
    ck_assert_double_eq(statt_two_sided(0, 63), 1);
    ck_assert_double_eq(statt_two_sided(NAN, 63), 1);
}
END_TEST

/* The tests of Student's t law. */
static Suite *statt_suite(void)
{
    Suite *s = suite_create("statt");
    TCase *tc = tcase_create("student");
    tcase_add_test(tc, tabulated_quantiles);
    tcase_add_test(tc, closed_forms);
    tcase_add_test(tc, normal_limit);
    tcase_add_test(tc, unbounded);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(statt_suite)
