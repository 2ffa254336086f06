/* test_triangle.c: ray-triangle intersection: inside, edges, corners, outside, windings,
 * degenerate. */
#include "triangle.h"
#include "testing.h"

/* The unit right triangle in the plane z = 0, counterclockwise seen from +z. */
static const Vec3 unit_corners[] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
static const Triangle unit = {&unit_corners[0], &unit_corners[1], &unit_corners[2]};

/* Returns the triangle whose corners are p[0], p[1] and p[2]. */
static Triangle corners(const Vec3 *p)
{
    return (Triangle){&p[0], &p[1], &p[2]};
}

/* Shoots a ray straight down -z at (x, y) from z = 1 against tri. */
static bool shoot(const Triangle *tri, double x, double y, TriangleHit *hit)
{
    return triangle_intersect(tri, ray(vec3(x, y, 1), vec3(0, 0, -1)), 0, INFINITY, hit);
}

START_TEST(inside)
{
    TriangleHit h;
    ck_assert(shoot(&unit, 0.25, 0.5, &h));
    ck_assert_double_eq(h.t, 1);
    /* p = a + beta (b - a) + gamma (c - a): (0.25, 0.5) has beta = 0.25, gamma = 0.5. */
    ck_assert_double_eq(h.beta, 0.25);
    ck_assert_double_eq(h.gamma, 0.5);
}
END_TEST

START_TEST(edges_and_corners_count)
{
    TriangleHit h;
    ck_assert(shoot(&unit, 0.5, 0, &h)); /* on edge ab */
    ck_assert_double_eq(h.gamma, 0);
    ck_assert(shoot(&unit, 0, 0.5, &h)); /* on edge ac */
    ck_assert_double_eq(h.beta, 0);
    ck_assert(shoot(&unit, 0.5, 0.5, &h)); /* on edge bc: beta + gamma = 1 */
    ck_assert_double_eq(h.beta + h.gamma, 1);
    ck_assert(shoot(&unit, 0, 0, &h)); /* corner a */
    ck_assert(shoot(&unit, 1, 0, &h)); /* corner b */
    ck_assert_double_eq(h.beta, 1);
    ck_assert(shoot(&unit, 0, 1, &h)); /* corner c */
    ck_assert_double_eq(h.gamma, 1);
}
END_TEST

START_TEST(outside)
{
    TriangleHit h;
    ck_assert(!shoot(&unit, 0.6, 0.6, &h));  /* beyond bc */
    ck_assert(!shoot(&unit, -0.1, 0.5, &h)); /* beyond ac */
    ck_assert(!shoot(&unit, 0.5, -0.1, &h)); /* beyond ab */
    ck_assert(!shoot(&unit, 2, 2, &h));
}
END_TEST

START_TEST(both_windings_are_hit)
{
    /* The same triangle clockwise from +z: hit at the same t, beta and gamma swapped,
     * and its normal points the other way. */
    Vec3 p[] = {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}};
    Triangle cw = corners(p);
    TriangleHit h;
    ck_assert(shoot(&cw, 0.25, 0.5, &h));
    ck_assert_double_eq(h.t, 1);
    ck_assert_double_eq(h.beta, 0.5);
    ck_assert_double_eq(h.gamma, 0.25);
    ck_assert_vec3_near(triangle_normal(&unit), vec3(0, 0, 1), 0);
    ck_assert_vec3_near(triangle_normal(&cw), vec3(0, 0, -1), 0);
}
END_TEST

START_TEST(parallel_and_behind)
{
    TriangleHit h;
    ck_assert(!triangle_intersect(&unit, ray(vec3(-1, 0.2, 0), vec3(1, 0, 0)), 0, INFINITY, &h));
    ck_assert(!triangle_intersect(&unit, ray(vec3(0.2, 0.2, 1), vec3(0, 0, 1)), 0, INFINITY, &h));
    ck_assert(!triangle_intersect(&unit, ray(vec3(0.2, 0.2, 1), vec3(0, 0, -1)), 0, 0.5, &h));
}
END_TEST

START_TEST(degenerate_triangles_never_hit)
{
    Vec3 on_line[] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, at_origin[3] = {{0}};
    Triangle line = corners(on_line), point = corners(at_origin);
    TriangleHit h = {-1, -1, -1};
    ck_assert(!shoot(&line, 0.5, 0, &h));
    ck_assert(!shoot(&point, 0, 0, &h));
    ck_assert_double_eq(h.t, -1);
}
END_TEST

START_TEST(barycentrics_rebuild_the_point)
{
    Vec3 p[] = {{1, 2, -7}, {-3, 5, -9}, {4, -1, -12}};
    Triangle t = corners(p);
    Ray r = ray(vec3(0.3, 0.1, 2), vec3_normalize(vec3(0.05, 0.2, -1)));
    TriangleHit h;
    ck_assert(triangle_intersect(&t, r, 0, INFINITY, &h));
    Vec3 q = vec3_add(p[0], vec3_add(vec3_scale(vec3_sub(p[1], p[0]), h.beta),
                                     vec3_scale(vec3_sub(p[2], p[0]), h.gamma)));
    ck_assert_vec3_near(q, ray_at(r, h.t), 1e-12);
    ck_assert(h.beta >= 0 && h.gamma >= 0 && h.beta + h.gamma <= 1);
}
END_TEST

/* The triangle's tests. */
static Suite *triangle_suite(void)
{
    Suite *s = suite_create("triangle");
    TCase *tc = tcase_create("intersect");
    tcase_add_test(tc, inside);
    tcase_add_test(tc, edges_and_corners_count);
    tcase_add_test(tc, outside);
    tcase_add_test(tc, both_windings_are_hit);
    tcase_add_test(tc, parallel_and_behind);
    tcase_add_test(tc, degenerate_triangles_never_hit);
    tcase_add_test(tc, barycentrics_rebuild_the_point);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(triangle_suite)
