/* test_secondary.c: the reflected direction, and where shadow and reflected rays start. */
#include "secondary.h"
#include "testing.h"

START_TEST(reflect_hand_picked)
{
    double h = sqrt(0.5);
    /* 45 degrees down onto a floor: 45 degrees up. */
    ck_assert_vec3_near(secondary_reflect(vec3(h, -h, 0), vec3(0, 1, 0)), vec3(h, h, 0), 1e-16);
    /* Head-on: straight back. */
    ck_assert_vec3_near(secondary_reflect(vec3(0, 0, -1), vec3(0, 0, 1)), vec3(0, 0, 1), 0);
    /* Along the surface: unchanged. */
    ck_assert_vec3_near(secondary_reflect(vec3(1, 0, 0), vec3(0, 1, 0)), vec3(1, 0, 0), 0);
    /* A wall x = const, seen at an angle: (0.6, 0, -0.8) becomes (-0.6, 0, -0.8). */
    ck_assert_vec3_near(secondary_reflect(vec3(0.6, 0, -0.8), vec3(-1, 0, 0)), vec3(-0.6, 0, -0.8),
                        1e-16);
}
END_TEST

START_TEST(reflect_properties)
{
    Vec3 d = vec3_normalize(vec3(0.3, -0.7, 0.2)), n = vec3_normalize(vec3(0.1, 1, -0.4));
    Vec3 r = secondary_reflect(d, n);
    ck_assert_double_eq_tol(vec3_length(r), 1, 1e-15);
    /* The angle with the normal is the same on the way out, on the other side. */
    ck_assert_double_eq_tol(vec3_dot(r, n), -vec3_dot(d, n), 1e-15);
    /* Reflecting twice gives d back; the normal's sign does not matter. */
    ck_assert_vec3_near(secondary_reflect(r, n), d, 4e-15);
    ck_assert_vec3_near(secondary_reflect(d, vec3_neg(n)), r, 4e-15);
}
END_TEST

START_TEST(secondary_rays_start_on_the_side_they_leave_by)
{
    Hit hit = {.point = {2, 0, -4}, .normal = {0, 1, 0}};
    Ray in = ray(vec3(0, 3, 0), vec3_normalize(vec3(2, -3, -4)));
    double offset = 0x1p-32, scale = 4; /* the largest coordinate of the point or origin */
    Ray up = secondary_ray(&hit, in, vec3(0, 1, 0), offset);
    ck_assert_vec3_near(up.origin, vec3(2, offset * scale, -4), 0);
    ck_assert_vec3_near(up.dir, vec3(0, 1, 0), 0);
    Ray down = secondary_ray(&hit, in, vec3_normalize(vec3(1, -1, 0)), offset);
    ck_assert_double_eq(down.origin.y, -offset * scale);
    Ray none = secondary_ray(&hit, in, vec3(0, 1, 0), 0);
    ck_assert_vec3_near(none.origin, hit.point, 0);
}
END_TEST

START_TEST(the_offset_grows_with_the_scene)
{
    /* A million times larger coordinates, a million times the offset: the same picture. */
    Hit hit = {.point = {2e6, 0, -4e6}, .normal = {0, 1, 0}};
    Ray in = ray(vec3(0, 3e6, 0), vec3(0, -1, 0));
    Ray up = secondary_ray(&hit, in, vec3(0, 1, 0), 0x1p-32);
    ck_assert_double_eq(up.origin.y, 0x1p-32 * 4e6);
    /* The ray's origin counts too: a far camera looking at a point near the origin. */
    Hit near = {.point = {0.001, 0, 0}, .normal = {0, 1, 0}};
    Ray far = ray(vec3(0, 5e5, 0), vec3(0, -1, 0));
    ck_assert_double_eq(secondary_ray(&near, far, vec3(0, 1, 0), 0x1p-32).origin.y, 0x1p-32 * 5e5);
}
END_TEST

/* The secondary-ray tests. */
static Suite *secondary_suite(void)
{
    Suite *s = suite_create("secondary");
    TCase *tc = tcase_create("rays");
    tcase_add_test(tc, reflect_hand_picked);
    tcase_add_test(tc, reflect_properties);
    tcase_add_test(tc, secondary_rays_start_on_the_side_they_leave_by);
    tcase_add_test(tc, the_offset_grows_with_the_scene);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(secondary_suite)
