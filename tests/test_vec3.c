/* test_vec3.c: vector and colour arithmetic on values worked out by hand. */
#include "color.h"
#include "ray.h"
#include "testing.h"

START_TEST(sums_and_scaling)
{
    Vec3 a = vec3(1, 2, 3), b = vec3(-4, 0.5, 2);
    ck_assert_vec3_near(vec3_add(a, b), vec3(-3, 2.5, 5), 0);
    ck_assert_vec3_near(vec3_sub(a, b), vec3(5, 1.5, 1), 0);
    ck_assert_vec3_near(vec3_scale(a, -2), vec3(-2, -4, -6), 0);
    ck_assert_vec3_near(vec3_add_scaled(a, b, 2), vec3(-7, 3, 7), 0);
    ck_assert_vec3_near(vec3_neg(b), vec3(4, -0.5, -2), 0);
}
END_TEST

START_TEST(dot_and_cross)
{
    Vec3 a = vec3(1, 2, 3), b = vec3(4, 5, 6);
    ck_assert_double_eq(vec3_dot(a, b), 32);
    /* (2*6 - 3*5, 3*4 - 1*6, 1*5 - 2*4) */
    ck_assert_vec3_near(vec3_cross(a, b), vec3(-3, 6, -3), 0);
    /* Right-handed: x cross y is z. */
    ck_assert_vec3_near(vec3_cross(vec3(1, 0, 0), vec3(0, 1, 0)), vec3(0, 0, 1), 0);
    ck_assert_vec3_near(vec3_cross(vec3(0, 1, 0), vec3(1, 0, 0)), vec3(0, 0, -1), 0);
    ck_assert_double_eq(vec3_dot(vec3_cross(a, b), a), 0);
}
END_TEST

START_TEST(lengths)
{
    ck_assert_double_eq(vec3_length(vec3(3, 4, 12)), 13);
    ck_assert_double_eq(vec3_length_squared(vec3(3, 4, 12)), 169);
    /* Within rounding: normalising multiplies by the reciprocal of the length. */
    ck_assert_vec3_near(vec3_normalize(vec3(0, -3, 4)), vec3(0, -0.6, 0.8), 1e-15);
    ck_assert_double_eq(vec3_max_abs(vec3(-7, 2, 5)), 7);
    ck_assert_vec3_near(vec3_min(vec3(1, -2, 3), vec3(0, 5, INFINITY)), vec3(0, -2, 3), 0);
    ck_assert_vec3_near(vec3_max(vec3(1, -2, 3), vec3(0, 5, -INFINITY)), vec3(1, 5, 3), 0);
    ck_assert_double_eq(vec3_axis(vec3(4, 5, 6), 0), 4);
    ck_assert_double_eq(vec3_axis(vec3(4, 5, 6), 1), 5);
    ck_assert_double_eq(vec3_axis(vec3(4, 5, 6), 2), 6);
    ck_assert(vec3_is_finite(vec3(1, 2, 3)));
    ck_assert(!vec3_is_finite(vec3(1, NAN, 3)));
    ck_assert(!vec3_is_finite(vec3(1, 2, -INFINITY)));
}
END_TEST

START_TEST(rays)
{
    Ray r = ray(vec3(1, 1, 1), vec3(0, 0, -1));
    ck_assert_vec3_near(ray_at(r, 2.5), vec3(1, 1, -1.5), 0);
}
END_TEST

START_TEST(colors)
{
    Color a = color(0.5, 0.25, 1), b = color(2, 4, 0);
    ck_assert_color_near(color_add(a, b), color(2.5, 4.25, 1), 0);
    ck_assert_color_near(color_mul(a, b), color(1, 1, 0), 0);
    ck_assert_color_near(color_scale(a, 4), color(2, 1, 4), 0);
    ck_assert(color_is_black(color(0, 0, 0)));
    ck_assert(!color_is_black(color(0, 1e-300, 0)));
    ck_assert(!color_is_finite(color(0, 0, NAN)));
}
END_TEST

/* The vector tests. */
static Suite *vec3_suite(void)
{
    Suite *s = suite_create("vec3");
    TCase *tc = tcase_create("arithmetic");
    tcase_add_test(tc, sums_and_scaling);
    tcase_add_test(tc, dot_and_cross);
    tcase_add_test(tc, lengths);
    tcase_add_test(tc, rays);
    tcase_add_test(tc, colors);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(vec3_suite)
