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

/* Asserts that box got, made by function what, is want to within 1e-15. */
static void check_box(Box got, Box want, const char *what)
{
    ck_assert_msg(vec3_length(vec3_sub(got.lo, want.lo)) <= 1e-15 &&
                      vec3_length(vec3_sub(got.hi, want.hi)) <= 1e-15,
                  "%s gives the box (%.9g, %.9g, %.9g) to (%.9g, %.9g, %.9g), not (%.9g, %.9g, "
                  "%.9g) to (%.9g, %.9g, %.9g): the least and greatest coordinates, grown by "
                  "box_pad",
                  what, got.lo.x, got.lo.y, got.lo.z, got.hi.x, got.hi.y, got.hi.z, want.lo.x,
                  want.lo.y, want.lo.z, want.hi.x, want.hi.y, want.hi.z);
}

START_TEST(boxes_of_surfaces)
{
    Sphere s = {vec3(1, 2, 3), 0.5, 0, 0};
    /* The centre plus and minus the radius, grown by 2^-20 of the largest coordinate. */
    double m = ldexp(3.5, -20);
    check_box(box_of_sphere(&s), (Box){vec3(0.5 - m, 1.5 - m, 2.5 - m), vec3(1.5 + m, 2.5 + m, 3.5 + m)},
              "box_of_sphere");
    /* Each corner gives some end: a the least x, b the least y and the greatest x, c the
     * greatest y; and in every order of the corners. */
    Vec3 p[] = {{0, 0, 0}, {2, -1, 0}, {1, 4, -3}};
    m = ldexp(4, -20);
    Box want = {vec3(-m, -1 - m, -3 - m), vec3(2 + m, 4 + m, m)};
    for (int k = 0; k < 3; k++) {
        Triangle tri = {&p[k], &p[(k + 1) % 3], &p[(k + 2) % 3]};
        check_box(box_of_triangle(&tri), want, "box_of_triangle");
    }
    ck_assert_double_eq(box_half_area(cube), 3);
    ck_assert_double_eq(box_half_area(box_empty()), 0);
    ck_assert_vec3_near(box_center(box_union(cube, (Box){{2, 2, 2}, {3, 3, 3}})), vec3(1.5, 1.5, 1.5),
                        0);
}
END_TEST

/* Asserts box_hit_face on the cube for the ray from o along d (normalised by nothing)
 * with (tmin, tmax): a hit at want_t with the normal want_n, or none when want_t < 0. */
static void check_face(Vec3 o, Vec3 d, double tmin, double tmax, double want_t, Vec3 want_n,
                       const char *why)
{
    double t = -1;
    Vec3 n = vec3(0, 0, 0);
    bool hit = box_hit_face(cube, ray(o, d), tmin, tmax, &t, &n);
    if (want_t < 0) {
        ck_assert_msg(!hit, "box_hit_face: the ray from (%g, %g, %g) along (%g, %g, %g) in (%g, %g) "
                      "meets the unit cube at t = %g; it should not (%s)",
                      o.x, o.y, o.z, d.x, d.y, d.z, tmin, tmax, t, why);
        return;
    }
    ck_assert_msg(hit && t == want_t && n.x == want_n.x && n.y == want_n.y && n.z == want_n.z,
                  "box_hit_face: the ray from (%g, %g, %g) along (%g, %g, %g) in (%g, %g) %s the "
                  "unit cube at t = %g, normal (%g, %g, %g); it should meet it at t = %g, normal "
                  "(%g, %g, %g) (%s)",
                  o.x, o.y, o.z, d.x, d.y, d.z, tmin, tmax, hit ? "meets" : "misses", t, n.x,
                  n.y, n.z, want_t, want_n.x, want_n.y, want_n.z, why);
}

START_TEST(faces_of_boxes)
{
    /* Negative directions enter at hi: the slab's two t swap. */
    check_face(vec3(3, 0.5, 0.5), vec3(-1, 0, 0), 0, INFINITY, 2, vec3(1, 0, 0),
               "towards -x it enters at x = 1");
    check_face(vec3(0.5, 0.5, 4), vec3(0, 0, -2), 0, INFINITY, 1.5, vec3(0, 0, 1),
               "towards -z it enters at z = 1");
    check_face(vec3(2.5, 1.5, 0.5), vec3(-1, -0.5, 0), 0, INFINITY, 1.5, vec3(1, 0, 0),
               "towards -x and -y it enters at x = 1, the later of the two entries");
    check_face(vec3(-1.5, 2, 0.5), vec3(1, -0.5, 0), 0, INFINITY, 2, vec3(0, 1, 0),
               "towards +x and -y it enters at y = 1, the later of the two entries");
    /* From inside, the face it leaves by, facing the origin. */
    check_face(vec3(0.5, 0.5, 0.5), vec3(0, -1, 0), 0, INFINITY, 0.5, vec3(0, 1, 0),
               "from inside it leaves by y = 0, the normal facing the origin");
    check_face(vec3(0.5, 0.5, 0.5), vec3(-0.5, 0, 0.25), 0, INFINITY, 1, vec3(1, 0, 0),
               "from inside it leaves by x = 0 before z = 1");
    check_face(vec3(0.5, 0.5, 0.5), vec3(0, 0, 1), 0, INFINITY, 0.5, vec3(0, 0, -1),
               "from inside it leaves by z = 1, the normal facing the origin");
    check_face(vec3(0.75, 0.75, 0.5), vec3(1, -1, 0), 0, INFINITY, 0.25, vec3(-1, 0, 0),
               "from inside it leaves by x = 1, whose axis is not the one it entered by");
    /* The same along +x: strict ends, and past the entry the exit. */
    check_face(vec3(-1, 0.5, 0.5), vec3(1, 0, 0), 0, 1, -1, vec3(0, 0, 0),
               "tmax = 1 is the entry itself, and t < tmax is strict");
    check_face(vec3(-1, 0.5, 0.5), vec3(1, 0, 0), 0, 1.5, 1, vec3(-1, 0, 0), "it enters at x = 0");
    check_face(vec3(-1, 0.5, 0.5), vec3(1, 0, 0), 1, 5, 2, vec3(-1, 0, 0),
               "with tmin at the entry it leaves at x = 1, the normal facing the origin");
    check_face(vec3(-1, 0.5, 0.5), vec3(1, 0, 0), 2, 5, -1, vec3(0, 0, 0),
               "tmin = 2 is the exit itself, and tmin < t is strict");
    /* Past the entry, the exit; strict ends; behind the origin, nothing. */
    check_face(vec3(3, 0.5, 0.5), vec3(-1, 0, 0), 2, INFINITY, 3, vec3(1, 0, 0),
               "with tmin at the entry it leaves at x = 0, t = 3");
    check_face(vec3(3, 0.5, 0.5), vec3(-1, 0, 0), 0, 2, -1, vec3(0, 0, 0),
               "tmax = 2 is the entry itself, and t < tmax is strict");
    check_face(vec3(3, 0.5, 0.5), vec3(-1, 0, 0), 3, INFINITY, -1, vec3(0, 0, 0),
               "tmin = 3 is the exit itself, and tmin < t is strict");
    check_face(vec3(3, 0.5, 0.5), vec3(1, 0, 0), 0, INFINITY, -1, vec3(0, 0, 0),
               "the box is behind the origin");
    check_face(vec3(3, 2, 0.5), vec3(-1, 0, 0), 0, INFINITY, -1, vec3(0, 0, 0),
               "parallel to the y slab, above it");
    /* An edge: x = 1 and y = 1 at the same t; the lower axis is the face. */
    check_face(vec3(2, 2, 0.5), vec3(-1, -1, 0), 0, INFINITY, 1, vec3(1, 0, 0),
               "at an edge, the face of the lower axis");
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
    tcase_add_test(tc, faces_of_boxes);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(box_suite)
