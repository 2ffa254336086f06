/* test_rng.c: PCG32 against its published outputs, and the placement of stratified points. */
#include <stdlib.h>

#include "rng.h"
#include "strata.h"
#include "testing.h"

START_TEST(pcg32_gives_the_reference_numbers)
{
    /* pcg32-demo of the reference C library: seed 42, stream 54, first six outputs. */
    Rng rng = rng_make(42, 54);
    const uint32_t expected[] = {0xa15c02b7, 0x7b47f409, 0xba1d3330,
                                 0x83d2f293, 0xbfa4784b, 0xcbed606e};
    for (int k = 0; k < 6; k++)
        ck_assert_uint_eq(rng_next(&rng), expected[k]);
}
END_TEST

START_TEST(uniform_numbers_lie_in_the_unit_interval_with_mean_one_half)
{
    Rng rng = rng_make(rng_hash(7), 1);
    double sum = 0;
    int n = 100000;
    for (int k = 0; k < n; k++) {
        double u = rng_uniform(&rng);
        ck_assert(u >= 0 && u < 1);
        sum += u;
    }
    /* The mean of n uniforms has standard deviation 1/sqrt(12 n) ~ 0.0009. */
    ck_assert_double_eq_tol(sum / n, 0.5, 0.004);
}
END_TEST

START_TEST(below_is_uniform_over_its_range)
{
    Rng rng = rng_make(1, 2);
    int counts[7] = {0};
    for (int k = 0; k < 70000; k++) {
        uint32_t r = rng_below(&rng, 7);
        ck_assert_uint_lt(r, 7);
        counts[r]++;
    }
    for (int k = 0; k < 7; k++)
        ck_assert_int_lt(abs(counts[k] - 10000), 500); /* 5 standard deviations */
}
END_TEST

START_TEST(jittered_points_fall_in_their_own_sub_square)
{
    Rng rng = rng_make(3, 4);
    int n = 5;
    for (int rep = 0; rep < 100; rep++)
        for (int k = 0; k < n * n; k++) {
            double u, v;
            strata_point(SAMPLING_JITTERED, &rng, k, n, &u, &v);
            ck_assert_int_eq((int)(u * n), k % n);
            ck_assert_int_eq((int)(v * n), k / n);
        }
}
END_TEST

START_TEST(a_shuffle_is_a_permutation)
{
    Rng rng = rng_make(5, 6);
    int perm[64], seen[64] = {0};
    strata_shuffle(&rng, perm, 64);
    for (int k = 0; k < 64; k++)
        seen[perm[k]]++;
    for (int k = 0; k < 64; k++)
        ck_assert_int_eq(seen[k], 1);
}
END_TEST

START_TEST(sampling_names)
{
    Sampling s;
    ck_assert(strata_sampling_from_name(NULL, &s) && s == SAMPLING_CORRELATED);
    ck_assert(strata_sampling_from_name("random", &s) && s == SAMPLING_RANDOM);
    ck_assert(strata_sampling_from_name("jittered", &s) && s == SAMPLING_JITTERED);
    ck_assert(!strata_sampling_from_name("stratified!", &s));
}
END_TEST

/* The suite of this file. */
static Suite *rng_suite(void)
{
    Suite *s = suite_create("rng");
    TCase *tc = tcase_create("rng");
    tcase_add_test(tc, pcg32_gives_the_reference_numbers);
    tcase_add_test(tc, uniform_numbers_lie_in_the_unit_interval_with_mean_one_half);
    tcase_add_test(tc, below_is_uniform_over_its_range);
    tcase_add_test(tc, jittered_points_fall_in_their_own_sub_square);
    tcase_add_test(tc, a_shuffle_is_a_permutation);
    tcase_add_test(tc, sampling_names);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(rng_suite)
