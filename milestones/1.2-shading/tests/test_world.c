/* test_world.c: the closest hit among spheres, planes and triangles, and its record. */
#include "testing.h"
#include "world.h"

/* A unit sphere at z = -5 in material 1, the floor y = -1 in material 0, a triangle at
 * z = -3 (counterclockwise from +z) in material 2. */
static Sphere spheres[] = {{.center = {0, 0, -5}, .radius = 1, .material = 1}};
static Plane planes[] = {{.normal = {0, 1, 0}, .d = 1, .material = 0}};
static Vec3 corners[] = {{2, 0, -3}, {4, 0, -3}, {2, 2, -3}};
static Face triangles[] = {{.corner = {0, 1, 2}, .material = 2}};
static const Scene scene = {.spheres = spheres,
                            .sphere_count = 1,
                            .planes = planes,
                            .plane_count = 1,
                            .vertices = corners,
                            .vertex_count = 3,
                            .triangles = triangles,
                            .triangle_count = 1};

START_TEST(nearest_sphere_hit)
{
    Hit h;
    ck_assert(world_hit(&scene, ray(vec3(0, 0, 0), vec3(0, 0, -1)), 0, INFINITY, &h));
    ck_assert_int_eq(h.kind, SURFACE_SPHERE);
    ck_assert_double_eq(h.t, 4);
    ck_assert_vec3_near(h.point, vec3(0, 0, -4), 0);
    ck_assert_vec3_near(h.normal, vec3(0, 0, 1), 0);
    ck_assert_int_eq(h.material, 1);
    ck_assert(!h.back_face);
}
END_TEST

START_TEST(closest_of_several)
{
    /* Towards the sphere's bottom, the floor and the sphere both lie ahead; the floor is
     * met first when the ray aims below the sphere's lowest point... */
    Hit h;
    Ray low = ray(vec3(0, 0, 0), vec3_normalize(vec3(0, -1, -2)));
    ck_assert(world_hit(&scene, low, 0, INFINITY, &h));
    ck_assert_int_eq(h.kind, SURFACE_PLANE);
    ck_assert_vec3_near(h.point, vec3(0, -1, -2), 1e-15);
    ck_assert_vec3_near(h.normal, vec3(0, 1, 0), 0);
    /* ...and a ray that meets the triangle (z = -3) before the floor (z = -10) hits it. */
    Ray right = ray(vec3(0, 0.5, 0), vec3_normalize(vec3(2.5, -0.15, -3)));
    ck_assert(world_hit(&scene, right, 0, INFINITY, &h));
    ck_assert_int_eq(h.kind, SURFACE_TRIANGLE);
    ck_assert_int_eq(h.material, 2);
    ck_assert_vec3_near(h.normal, vec3(0, 0, 1), 0);
    ck_assert_double_eq_tol(h.point.z, -3, 1e-14);
}
END_TEST

START_TEST(back_faces)
{
    /* From behind the triangle (z < -3) looking towards +z. */
    Hit h;
    ck_assert(world_hit(&scene, ray(vec3(2.5, 0.5, -3.5), vec3(0, 0, 1)), 0, INFINITY, &h));
    ck_assert_int_eq(h.kind, SURFACE_TRIANGLE);
    ck_assert(h.back_face);
    /* From under the floor. */
    ck_assert(world_hit(&scene, ray(vec3(0, -3, 20), vec3(0, 1, 0)), 0, INFINITY, &h));
    ck_assert_int_eq(h.kind, SURFACE_PLANE);
    ck_assert(h.back_face);
    /* From inside the sphere: its inside is a back face, but not a wrongly wound one. */
    ck_assert(world_hit(&scene, ray(vec3(0, 0, -5), vec3(0, 0, -1)), 0, INFINITY, &h));
    ck_assert_int_eq(h.kind, SURFACE_SPHERE);
    ck_assert_double_eq(h.t, 1);
    ck_assert(h.back_face);
    ck_assert_vec3_near(h.normal, vec3(0, 0, -1), 0);
}
END_TEST

START_TEST(nothing_hit)
{
    Hit h;
    ck_assert(!world_hit(&scene, ray(vec3(0, 0, 0), vec3(0, 1, 0)), 0, INFINITY, &h));
    ck_assert(!world_hit(&scene, ray(vec3(0, 0, 0), vec3(0, 0, -1)), 0, 3.5, &h));
}
END_TEST

/* The closest-hit tests. */
static Suite *world_suite(void)
{
    Suite *s = suite_create("world");
    TCase *tc = tcase_create("closest hit");
    tcase_add_test(tc, nearest_sphere_hit);
    tcase_add_test(tc, closest_of_several);
    tcase_add_test(tc, back_faces);
    tcase_add_test(tc, nothing_hit);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(world_suite)
