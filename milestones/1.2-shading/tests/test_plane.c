/* test_plane.c: ray-plane intersection: a hit, from behind, parallel, behind the ray, both
 * conventions. */
#include <stdio.h>

#include "plane.h"
#include "testing.h"

/* The floor y = -2 in the lecture's form p.N + d = 0: N = (0,1,0), d = 2. */
static const Plane floor_at_minus_2 = {.normal = {0, 1, 0}, .d = 2};

START_TEST(hit_from_the_front)
{
    double t = -1;
    ck_assert(
        plane_intersect(&floor_at_minus_2, ray(vec3(0, 0, 0), vec3(0, -1, 0)), 0, INFINITY, &t));
    ck_assert_double_eq(t, 2);
    /* At 45 degrees the path to y = -2 is 2 sqrt 2 long. */
    Ray slant = ray(vec3(1, 0, 0), vec3_normalize(vec3(1, -1, 0)));
    ck_assert(plane_intersect(&floor_at_minus_2, slant, 0, INFINITY, &t));
    ck_assert_double_eq_tol(t, 2 * sqrt(2), 1e-15);
    ck_assert_vec3_near(ray_at(slant, t), vec3(3, -2, 0), 1e-15);
}
END_TEST

START_TEST(hit_from_behind)
{
    double t = -1;
    ck_assert(
        plane_intersect(&floor_at_minus_2, ray(vec3(0, -5, 0), vec3(0, 1, 0)), 0, INFINITY, &t));
    ck_assert_double_eq(t, 3);
}
END_TEST

START_TEST(parallel_rays_miss)
{
    double t = -1;
    ck_assert(
        !plane_intersect(&floor_at_minus_2, ray(vec3(0, 0, 0), vec3(1, 0, 0)), 0, INFINITY, &t));
    /* Even one running inside the plane: there is no single point to return. */
    ck_assert(
        !plane_intersect(&floor_at_minus_2, ray(vec3(0, -2, 0), vec3(0, 0, 1)), 0, INFINITY, &t));
}
END_TEST

START_TEST(plane_behind_the_ray)
{
    double t = -1;
    ck_assert(
        !plane_intersect(&floor_at_minus_2, ray(vec3(0, 0, 0), vec3(0, 1, 0)), 0, INFINITY, &t));
    ck_assert(!plane_intersect(&floor_at_minus_2, ray(vec3(0, 0, 0), vec3(0, -1, 0)), 0, 1.5, &t));
}
END_TEST

START_TEST(unnormalised_normal)
{
    /* 2y + 4 = 0 is the same plane; the formula does not need |N| = 1. */
    Plane p = {.normal = {0, 2, 0}, .d = 4};
    double t = -1;
    ck_assert(plane_intersect(&p, ray(vec3(0, 0, 0), vec3(0, -1, 0)), 0, INFINITY, &t));
    ck_assert_double_eq(t, 2);
}
END_TEST

/* Loads a one-plane scene in a convention and returns where a ray down from y = 100 meets it. */
static double floor_height(const char *plane_line, Convention convention)
{
    FILE *f = fopen("p.scn", "w");
    fprintf(f, "c 0 0 0 0 0 -1 1 1 1 4 4\nm 1 1 1 0 0 0 1 0 0 0\n%s\n", plane_line);
    fclose(f);
    Scene scene;
    SceneLoadOptions opts = {.convention = convention, .forced = true, .messages = stderr};
    ck_assert(scene_load(&scene, "p.scn", &opts));
    double t = -1;
    ck_assert(
        plane_intersect(&scene.planes[0], ray(vec3(0, 100, 0), vec3(0, -1, 0)), 0, INFINITY, &t));
    scene_free(&scene);
    return 100 - t;
}

START_TEST(both_conventions)
{
    /* Lecture: p.N + d = 0, so p 0 1 0 40 is y = -40; fall2016: p.N = d, so it is y = 40. */
    ck_assert_double_eq(floor_height("p 0 1 0 40", CONVENTION_LECTURE), -40);
    ck_assert_double_eq(floor_height("p 0 1 0 40", CONVENTION_FALL2016), 40);
    ck_assert_double_eq(floor_height("p 0 1 0 -40", CONVENTION_FALL2016), -40);
    /* A normal of length 4: N is normalised and d stays the distance along it (slide
     * 45, "d is measured in direction of normal"), as every Fall 2016 renderer reads it. */
    ck_assert_double_eq(floor_height("p 0 4 0 12", CONVENTION_LECTURE), -12);
    ck_assert_double_eq(floor_height("p 0 2 0 -40", CONVENTION_FALL2016), -40);
}
END_TEST

/* The plane's tests. */
static Suite *plane_suite(void)
{
    Suite *s = suite_create("plane");
    TCase *tc = tcase_create("intersect");
    tcase_add_test(tc, hit_from_the_front);
    tcase_add_test(tc, hit_from_behind);
    tcase_add_test(tc, parallel_rays_miss);
    tcase_add_test(tc, plane_behind_the_ray);
    tcase_add_test(tc, unnormalised_normal);
    tcase_add_test(tc, both_conventions);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(plane_suite)
