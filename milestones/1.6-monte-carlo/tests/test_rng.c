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
    for (int k = 0; k < 6; k++) {
        uint32_t got = rng_next(&rng);
        ck_assert_msg(got == expected[k],
                      "output %d of rng_next from seed 42, stream 54 is 0x%08x, not 0x%08x as "
                      "the reference library's pcg32-demo prints: rng_make and rng_next must "
                      "step as pcg32_srandom_r and pcg32_random_r do",
                      k, got, expected[k]);
    }
}
END_TEST

START_TEST(uniform_numbers_lie_in_the_unit_interval_with_mean_one_half)
{
    Rng rng = rng_make(rng_hash(7), 1);
    double sum = 0;
    int n = 100000;
    for (int k = 0; k < n; k++) {
        double u = rng_uniform(&rng);
        ck_assert_msg(u >= 0 && u < 1,
                      "rng_uniform returned %.17g (number %d), outside [0, 1): it is 32 random "
                      "bits over 2^32",
                      u, k);
        sum += u;
    }
    /* The mean of n uniforms has standard deviation 1/sqrt(12 n) ~ 0.0009. */
    ck_assert_msg(fabs(sum / n - 0.5) <= 0.004,
                  "the mean of %d numbers of rng_uniform is %.4f, not 0.5 within 0.004 (4 "
                  "standard deviations): they are not uniform over [0, 1)",
                  n, sum / n);
}
END_TEST

START_TEST(below_is_uniform_over_its_range)
{
    Rng rng = rng_make(1, 2);
    int counts[7] = {0};
    for (int k = 0; k < 70000; k++) {
        uint32_t r = rng_below(&rng, 7);
        ck_assert_msg(r < 7, "rng_below(rng, 7) returned %u, not a number from 0 to 6", r);
        counts[r]++;
    }
    for (int k = 0; k < 7; k++) /* 500: 5 standard deviations */
        ck_assert_msg(abs(counts[k] - 10000) < 500,
                      "of 70000 numbers of rng_below(rng, 7), %d are %d, not 10000 within 500 (5 "
                      "standard deviations): each of 0 to 6 must be as likely",
                      counts[k], k);
}
END_TEST

START_TEST(jittered_points_fall_in_their_own_sub_square)
{
    Rng rng = rng_make(3, 4);
    int n = 5;
    for (int rep = 0; rep < 100; rep++)
        for (int k = 0; k < n * n; k++) {
            double u = NAN, v = NAN;
            strata_point(SAMPLING_JITTERED, &rng, k, n, &u, &v);
            ck_assert_msg(u >= 0 && u < 1 && v >= 0 && v < 1,
                          "strata_point, jittered, gives sample %d of 5 x 5 at (%g, %g), not a "
                          "point of the unit square [0, 1)^2",
                          k, u, v);
            ck_assert_msg((int)(u * n) == k % n && (int)(v * n) == k / n,
                          "strata_point, jittered, puts sample %d of 5 x 5 at (%.4f, %.4f), in "
                          "sub-square (%d, %d), not in its own, (%d, %d): sample k goes in column "
                          "k %% n and row k / n (the sub-squares counted row by row), uniform "
                          "within it",
                          k, u, v, (int)(u * n), (int)(v * n), k % n, k / n);
        }
}
END_TEST

START_TEST(a_shuffle_is_a_permutation)
{
    Rng rng = rng_make(5, 6);
    int perm[64], seen[64] = {0};
    for (int k = 0; k < 64; k++)
        perm[k] = -1;
    strata_shuffle(&rng, perm, 64);
    for (int k = 0; k < 64; k++) {
        ck_assert_msg(perm[k] >= 0 && perm[k] < 64,
                      "strata_shuffle of 64 leaves perm[%d] = %d, not one of 0 to 63: it fills "
                      "perm with 0 .. count-1 first, then swaps (Fisher-Yates)",
                      k, perm[k]);
        seen[perm[k]]++;
    }
    for (int k = 0; k < 64; k++)
        ck_assert_msg(seen[k] == 1,
                      "strata_shuffle of 64 puts %d in perm %d times, not once: a shuffle "
                      "(Fisher-Yates) only swaps entries, so that 0 .. count-1 each stay once",
                      k, seen[k]);
}
END_TEST

START_TEST(sampling_names)
{
    const char *names[] = {NULL, "random", "jittered"};
    const Sampling want[] = {SAMPLING_CORRELATED, SAMPLING_RANDOM, SAMPLING_JITTERED};
    for (int k = 0; k < 3; k++) {
        Sampling s = (Sampling)-1;
        bool known = strata_sampling_from_name(names[k], &s);
        ck_assert_msg(known && s == want[k],
                      "strata_sampling_from_name(%s%s%s) %s %d, not %d: the names are random, "
                      "jittered and correlated, and none (NULL) is correlated",
                      names[k] ? "\"" : "", names[k] ? names[k] : "NULL", names[k] ? "\"" : "",
                      known ? "gives" : "refuses it, leaving", (int)s, (int)want[k]);
    }
    Sampling s;
    ck_assert_msg(!strata_sampling_from_name("stratified!", &s),
                  "strata_sampling_from_name accepts \"stratified!\", which is no sampling's name");
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
