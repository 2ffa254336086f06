/* test_sphere.c: ray-sphere intersection: miss, graze, two hits, from inside, behind. */
#include "sphere.h"
#include "testing.h"

static const Sphere unit_at_minus_5 = {.center = {0, 0, -5}, .radius = 1};

START_TEST(two_hits_give_the_nearer)
{
    double t = -1;
    Ray r = ray(vec3(0, 0, 0), vec3(0, 0, -1));
    ck_assert(sphere_intersect(&unit_at_minus_5, r, 0, INFINITY, &t));
    ck_assert_double_eq(t, 4);
}
END_TEST

START_TEST(the_farther_hit_past_tmin)
{
    double t = -1;
    Ray r = ray(vec3(0, 0, 0), vec3(0, 0, -1));
    ck_assert(sphere_intersect(&unit_at_minus_5, r, 4.5, INFINITY, &t));
    ck_assert_double_eq(t, 6);
}
END_TEST

START_TEST(no_hit_beyond_tmax)
{
    double t = -1;
    Ray r = ray(vec3(0, 0, 0), vec3(0, 0, -1));
    ck_assert(!sphere_intersect(&unit_at_minus_5, r, 0, 3.9, &t));
}
END_TEST

START_TEST(miss)
{
    double t = -1;
    ck_assert(
        !sphere_intersect(&unit_at_minus_5, ray(vec3(0, 0, 0), vec3(0, 1, 0)), 0, INFINITY, &t));
    /* Towards (0, 1.5, -5): the line passes the centre at 7.5 / sqrt(27.25) = 1.44 > 1. */
    Ray beside = ray(vec3(0, 0, 0), vec3_normalize(vec3(0, 1.5, -5)));
    ck_assert(!sphere_intersect(&unit_at_minus_5, beside, 0, INFINITY, &t));
}
END_TEST

START_TEST(graze)
{
    /* A ray along x = 1 touches the unit sphere at (1, 0, -5): one hit, t = 5. */
    double t = -1;
    Ray r = ray(vec3(1, 0, 0), vec3(0, 0, -1));
    ck_assert(sphere_intersect(&unit_at_minus_5, r, 0, INFINITY, &t));
    ck_assert_double_eq(t, 5);
    /* A hair further out it misses. */
    Ray beside = ray(vec3(1 + 1e-9, 0, 0), vec3(0, 0, -1));
    ck_assert(!sphere_intersect(&unit_at_minus_5, beside, 0, INFINITY, &t));
}
END_TEST

START_TEST(origin_inside)
{
    /* From the centre of a sphere of radius 2 the only hit ahead is the far side, t = 2. */
    Sphere s = {.center = {0, 0, 0}, .radius = 2};
    double t = -1;
    ck_assert(sphere_intersect(&s, ray(vec3(0, 0, 0), vec3(1, 0, 0)), 0, INFINITY, &t));
    ck_assert_double_eq(t, 2);
    /* From (1,0,0) along +x: roots -3 and 1. */
    ck_assert(sphere_intersect(&s, ray(vec3(1, 0, 0), vec3(1, 0, 0)), 0, INFINITY, &t));
    ck_assert_double_eq(t, 1);
}
END_TEST

START_TEST(sphere_behind)
{
    /* Both roots (4 and 6 units back) are negative. */
    Sphere s = {.center = {0, 0, 5}, .radius = 1};
    double t = -1;
    ck_assert(!sphere_intersect(&s, ray(vec3(0, 0, 0), vec3(0, 0, -1)), 0, INFINITY, &t));
}
END_TEST

START_TEST(direction_need_not_be_unit)
{
    /* With d = (0,0,-2), r(2) = (0,0,-4): the same point, half the t. */
    double t = -1;
    ck_assert(
        sphere_intersect(&unit_at_minus_5, ray(vec3(0, 0, 0), vec3(0, 0, -2)), 0, INFINITY, &t));
    ck_assert_double_eq(t, 2);
}
END_TEST

START_TEST(far_small_sphere_keeps_its_size)
{
    /* A unit sphere 1e8 away: the naive b^2 - c rounds to 0 (1e16 - 1 is not a
     * double), which would make it a single point. The stable form finds both
     * roots, 1e8 - 1 and 1e8 + 1. */
    Sphere s = {.center = {0, 0, -1e8}, .radius = 1};
    double t = -1;
    Ray r = ray(vec3(0, 0, 0), vec3(0, 0, -1));
    ck_assert(sphere_intersect(&s, r, 0, INFINITY, &t));
    ck_assert_double_eq_tol(t, 1e8 - 1, 1e-6);
    ck_assert(sphere_intersect(&s, r, 1e8, INFINITY, &t));
    ck_assert_double_eq_tol(t, 1e8 + 1, 1e-6);
    /* And a ray half a radius off the axis still hits. */
    ck_assert(sphere_intersect(&s, ray(vec3(0.5, 0, 0), vec3(0, 0, -1)), 0, INFINITY, &t));
}
END_TEST

/* The sphere's tests. */
static Suite *sphere_suite(void)
{
    Suite *s = suite_create("sphere");
    TCase *tc = tcase_create("intersect");
    tcase_add_test(tc, two_hits_give_the_nearer);
    tcase_add_test(tc, the_farther_hit_past_tmin);
    tcase_add_test(tc, no_hit_beyond_tmax);
    tcase_add_test(tc, miss);
    tcase_add_test(tc, graze);
    tcase_add_test(tc, origin_inside);
    tcase_add_test(tc, sphere_behind);
    tcase_add_test(tc, direction_need_not_be_unit);
    tcase_add_test(tc, far_small_sphere_keeps_its_size);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(sphere_suite)
