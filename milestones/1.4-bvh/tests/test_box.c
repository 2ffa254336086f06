/* test_box.c: the slab test on hand-computed cases, and the boxes of spheres and triangles. */
#include "box.h"
#include "testing.h"

/* The unit cube [0, 1]^3. */
static const Box cube = {{0, 0, 0}, {1, 1, 1}};

/* Runs box_hit on the cube for the ray from o along d, asserting a finite t when it hits. */
static bool cube_hit(Vec3 o, Vec3 d, double tmin, double tmax, double *t)
{
    BoxRay br = box_ray(ray(o, d));
    bool hit = box_hit(cube, &br, tmin, tmax, t);
    if (hit)
        ck_assert_msg(!isnan(*t), "NaN entry t");
    return hit;
}

START_TEST(axis_parallel_rays)
{
    double t;
    /* Along +x through the middle: enters at x = 0, one unit away. */
    ck_assert(cube_hit(vec3(-1, 0.5, 0.5), vec3(1, 0, 0), 0, INFINITY, &t));
    ck_assert_double_eq(t, 1);
    /* Along -x from the other side: enters at x = 1, two units away. */
    ck_assert(cube_hit(vec3(3, 0.5, 0.5), vec3(-1, 0, 0), 0, INFINITY, &t));
    ck_assert_double_eq(t, 2);
    /* Parallel to the x slab, beside it: (lo - o) * inf is +inf on both sides, a miss. */
    ck_assert(!cube_hit(vec3(-1, 2, 0.5), vec3(1, 0, 0), 0, INFINITY, &t));
    ck_assert(!cube_hit(vec3(-1, -0.5, 0.5), vec3(1, 0, 0), 0, INFINITY, &t));
    /* Pointing away: the box is behind, at t = -2 .. -1. */
    ck_assert(!cube_hit(vec3(-1, 0.5, 0.5), vec3(-1, 0, 0), 0, INFINITY, &t));
}
END_TEST

START_TEST(rays_in_a_face_plane)
{
    double t;
    /* In the plane y = 1 of the top face: 0 * inf = NaN must not decide; the closed box
     * counts its faces, so this is a hit, entering at x = 0. */
    ck_assert(cube_hit(vec3(-1, 1, 0.5), vec3(1, 0, 0), 0, INFINITY, &t));
    ck_assert_double_eq(t, 1);
    /* The same in the plane y = 0, with the direction's y a negative zero (1/-0 = -inf). */
    ck_assert(cube_hit(vec3(-1, 0, 0.5), vec3(1, -0.0, 0), 0, INFINITY, &t));
    ck_assert_double_eq(t, 1);
    /* On an edge line, x = 0 and z = 1, travelling along y with -0 in x and z. */
    ck_assert(cube_hit(vec3(0, -2, 1), vec3(-0.0, 1, -0.0), 0, INFINITY, &t));
    ck_assert_double_eq(t, 2);
    /* Through a corner edge diagonally: touches the edge x = 0, y = 0 at t = sqrt 2. */
    double h = sqrt(0.5);
    ck_assert(cube_hit(vec3(-1, -1, 0.5), vec3(h, h, 0), 0, INFINITY, &t));
}
END_TEST

START_TEST(origin_inside)
{
    double t;
    /* From the centre the interval starts at tmin itself. */
    ck_assert(cube_hit(vec3(0.5, 0.5, 0.5), vec3(0, 0, 1), 0, INFINITY, &t));
    ck_assert_double_eq(t, 0);
    /* On the face: starting on the plane x = 0, moving into the box and out of it. */
    ck_assert(cube_hit(vec3(0, 0.5, 0.5), vec3(1, 0, 0), 0, INFINITY, &t));
    ck_assert(cube_hit(vec3(0, 0.5, 0.5), vec3(-1, 0, 0), 0, INFINITY, &t));
    ck_assert_double_eq(t, 0);
    /* The face a ray leaves through, from inside: z = 1 at t = 0.5, normal towards the origin. */
    Vec3 normal;
    ck_assert(box_hit_face(cube, ray(vec3(0.5, 0.5, 0.5), vec3(0, 0, 1)), 0, INFINITY, &t, &normal));
    ck_assert_double_eq(t, 0.5);
    ck_assert_vec3_near(normal, vec3(0, 0, -1), 0);
}
END_TEST

START_TEST(tmin_tmax_limits)
{
    double t;
    Vec3 o = vec3(-1, 0.5, 0.5), d = vec3(1, 0, 0); /* inside for 1 <= t <= 2 */
    ck_assert(!cube_hit(o, d, 0, 0.5, &t));
    ck_assert(cube_hit(o, d, 0, 1, &t)); /* closed: touching counts */
    ck_assert(cube_hit(o, d, 2, 5, &t));
    ck_assert_double_eq(t, 2);
    ck_assert(!cube_hit(o, d, 2.5, 5, &t));
    ck_assert(cube_hit(o, d, 1.5, 1.6, &t));
    ck_assert_double_eq(t, 1.5);
    /* The face test is strict, like every surface: tmin < t < tmax. */
    Vec3 normal;
    ck_assert(!box_hit_face(cube, ray(o, d), 0, 1, &t, &normal));
    ck_assert(box_hit_face(cube, ray(o, d), 0, 1.5, &t, &normal));
    ck_assert_double_eq(t, 1);
    ck_assert_vec3_near(normal, vec3(-1, 0, 0), 0);
    /* Past the entry, the exit face: x = 1 at t = 2. */
    ck_assert(box_hit_face(cube, ray(o, d), 1, 5, &t, &normal));
    ck_assert_double_eq(t, 2);
    ck_assert_vec3_near(normal, vec3(-1, 0, 0), 0);
    ck_assert(!box_hit_face(cube, ray(o, d), 2, 5, &t, &normal));
}
END_TEST

START_TEST(infinite_inverse_directions)
{
    BoxRay br = box_ray(ray(vec3(0, 0, 0), vec3(0.0, -0.0, 1)));
    ck_assert(isinf(br.inv_dir.x) && br.inv_dir.x > 0);
    ck_assert(isinf(br.inv_dir.y) && br.inv_dir.y < 0);
    ck_assert_double_eq(br.inv_dir.z, 1);
    /* From the corner (0, 0, 0) along z: on two face planes at once, a hit at t = 0. */
    double t;
    ck_assert(box_hit(cube, &br, 0, INFINITY, &t));
    ck_assert_double_eq(t, 0);
    /* A flat box (a triangle in the plane z = 0.5): crossed at exactly one t. */
    Box flat = {{0, 0, 0.5}, {1, 1, 0.5}};
    BoxRay down = box_ray(ray(vec3(0.5, 0.5, 2), vec3(0, 0, -1)));
    ck_assert(box_hit(flat, &down, 0, INFINITY, &t));
    ck_assert_double_eq(t, 1.5);
    ck_assert(!box_hit(flat, &down, 0, 1.4, &t));
}
END_TEST

START_TEST(boxes_of_surfaces)
{
    Sphere s = {vec3(1, 2, 3), 0.5, 0, 0};
    Box b = box_of_sphere(&s);
    /* The centre plus and minus the radius, grown by 2^-20 of the largest coordinate. */
    double m = ldexp(3.5, -20);
    ck_assert_vec3_near(b.lo, vec3(0.5 - m, 1.5 - m, 2.5 - m), 1e-15);
    ck_assert_vec3_near(b.hi, vec3(1.5 + m, 2.5 + m, 3.5 + m), 1e-15);
    Vec3 p[] = {{0, 0, 0}, {2, -1, 0}, {1, 4, 0}};
    Triangle tri = {&p[0], &p[1], &p[2]};
    b = box_of_triangle(&tri);
    m = ldexp(4, -20);
    ck_assert_vec3_near(b.lo, vec3(-m, -1 - m, -m), 1e-15);
    ck_assert_vec3_near(b.hi, vec3(2 + m, 4 + m, m), 1e-15);
    ck_assert(box_contains(b, (Box){p[1], p[2]}));
    ck_assert_double_eq(box_half_area(cube), 3);
    ck_assert_double_eq(box_half_area(box_empty()), 0);
    ck_assert_vec3_near(box_center(box_union(cube, (Box){{2, 2, 2}, {3, 3, 3}})), vec3(1.5, 1.5, 1.5),
                        0);
}
END_TEST

/* Collects the tests of box.c. */
static Suite *box_suite(void)
{
    Suite *s = suite_create("box");
    TCase *tc = tcase_create("box");
    tcase_add_test(tc, axis_parallel_rays);
    tcase_add_test(tc, rays_in_a_face_plane);
    tcase_add_test(tc, origin_inside);
    tcase_add_test(tc, tmin_tmax_limits);
    tcase_add_test(tc, infinite_inverse_directions);
    tcase_add_test(tc, boxes_of_surfaces);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(box_suite)
