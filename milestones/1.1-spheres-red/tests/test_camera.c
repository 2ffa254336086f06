/* test_camera.c: the camera frame and the primary rays, against values worked out by hand. */
#include "camera.h"
#include "testing.h"

/* A camera spec with the given eye and view direction, a 2 x 2 image plane at d = 1. */
static CameraSpec spec(Vec3 eye, Vec3 view, int nx, int ny)
{
    return (CameraSpec){
        .eye = eye, .view = view, .focal = 1, .width = 2, .height = 2, .nx = nx, .ny = ny};
}

/* Asserts that the frame is orthonormal and right-handed: u x v = w. */
static void assert_orthonormal(const Camera *c)
{
    ck_assert_double_eq_tol(vec3_length(c->u), 1, 1e-15);
    ck_assert_double_eq_tol(vec3_length(c->v), 1, 1e-15);
    ck_assert_double_eq_tol(vec3_length(c->w), 1, 1e-15);
    ck_assert_double_eq_tol(vec3_dot(c->u, c->v), 0, 1e-15);
    ck_assert_double_eq_tol(vec3_dot(c->v, c->w), 0, 1e-15);
    ck_assert_double_eq_tol(vec3_dot(c->w, c->u), 0, 1e-15);
    ck_assert_vec3_near(vec3_cross(c->u, c->v), c->w, 1e-15);
}

START_TEST(frame_looking_down_minus_z)
{
    Camera c = camera_make(&(CameraSpec){
        .view = vec3(0, 0, -1), .focal = 1, .width = 2, .height = 2, .nx = 2, .ny = 2});
    ck_assert_vec3_near(c.u, vec3(1, 0, 0), 0);
    ck_assert_vec3_near(c.v, vec3(0, 1, 0), 0);
    ck_assert_vec3_near(c.w, vec3(0, 0, 1), 0);
}
END_TEST

START_TEST(frame_looking_along_plus_x)
{
    /* D x up = (1,0,0) x (0,1,0) = (0,0,1): right is +z; v = u x D = (0,1,0). */
    Camera c = camera_make(&(CameraSpec){
        .view = vec3(1, 0, 0), .focal = 1, .width = 2, .height = 2, .nx = 2, .ny = 2});
    ck_assert_vec3_near(c.u, vec3(0, 0, 1), 0);
    ck_assert_vec3_near(c.v, vec3(0, 1, 0), 0);
    ck_assert_vec3_near(c.w, vec3(-1, 0, 0), 0);
}
END_TEST

START_TEST(frame_tilted_down)
{
    /* D = (0,-1,-1)/sqrt 2: u = (1,0,0), v = (0,1,-1)/sqrt 2, w = (0,1,1)/sqrt 2. */
    Camera c = camera_make(&(CameraSpec){
        .view = vec3(0, -1, -1), .focal = 1, .width = 2, .height = 2, .nx = 2, .ny = 2});
    double h = sqrt(0.5);
    ck_assert_vec3_near(c.u, vec3(1, 0, 0), 1e-15);
    ck_assert_vec3_near(c.v, vec3(0, h, -h), 1e-15);
    ck_assert_vec3_near(c.w, vec3(0, h, h), 1e-15);
    assert_orthonormal(&c);
}
END_TEST

START_TEST(frame_does_not_depend_on_the_length_of_d)
{
    Camera a = camera_make(&(CameraSpec){
        .view = vec3(0.3, -0.4, -1), .focal = 1, .width = 2, .height = 2, .nx = 2, .ny = 2});
    Camera b = camera_make(&(CameraSpec){
        .view = vec3(3, -4, -10), .focal = 1, .width = 2, .height = 2, .nx = 2, .ny = 2});
    ck_assert_vec3_near(a.u, b.u, 1e-15);
    ck_assert_vec3_near(a.v, b.v, 1e-15);
    ck_assert_vec3_near(a.w, b.w, 1e-15);
    assert_orthonormal(&a);
}
END_TEST

START_TEST(frame_looking_straight_down)
{
    /* D parallel to up: the fallback up is -z, so u = (1,0,0) and v = (0,0,-1). */
    CameraSpec s = spec(vec3(0, 10, 0), vec3(0, -3, 0), 2, 2);
    Camera c = camera_make(&s);
    ck_assert_vec3_near(c.u, vec3(1, 0, 0), 0);
    ck_assert_vec3_near(c.v, vec3(0, 0, -1), 0);
    ck_assert_vec3_near(c.w, vec3(0, 1, 0), 0);
    assert_orthonormal(&c);
    Ray r = camera_ray(&c, 1, 1);
    ck_assert(vec3_is_finite(r.dir));
    ck_assert_vec3_near(r.dir, vec3(0, -1, 0), 1e-15);
}
END_TEST

START_TEST(frame_looking_straight_up)
{
    /* The fallback up is +z, so u = (1,0,0) and v = (0,0,1): still right-handed. */
    Camera c = camera_make(&(CameraSpec){
        .view = vec3(0, 1, 0), .focal = 1, .width = 2, .height = 2, .nx = 2, .ny = 2});
    ck_assert_vec3_near(c.u, vec3(1, 0, 0), 0);
    ck_assert_vec3_near(c.v, vec3(0, 0, 1), 0);
    ck_assert_vec3_near(c.w, vec3(0, -1, 0), 0);
    assert_orthonormal(&c);
}
END_TEST

START_TEST(image_plane_is_centred)
{
    CameraSpec s = {
        .view = vec3(0, 0, -1), .focal = 35, .width = 35, .height = 25, .nx = 320, .ny = 240};
    Camera c = camera_make(&s);
    ck_assert_double_eq(c.left, -17.5);
    ck_assert_double_eq(c.right, 17.5);
    ck_assert_double_eq(c.bottom, -12.5);
    ck_assert_double_eq(c.top, 12.5);
}
END_TEST

START_TEST(ray_of_the_bottom_left_pixel)
{
    /* 2 x 2 pixels on [-1,1]^2: pixel (0,0)'s centre is (u,v) = (-0.5,-0.5), so
     * the direction is (-0.5, -0.5, -1) / sqrt(1.5). */
    CameraSpec s = spec(vec3(1, 2, 3), vec3(0, 0, -1), 2, 2);
    Camera c = camera_make(&s);
    Ray r = camera_ray(&c, 0 + 0.5, 0 + 0.5);
    double k = 1 / sqrt(1.5);
    ck_assert_vec3_near(r.origin, vec3(1, 2, 3), 0);
    ck_assert_vec3_near(r.dir, vec3(-0.5 * k, -0.5 * k, -k), 1e-15);
}
END_TEST

START_TEST(ray_of_the_top_right_pixel)
{
    /* 4 x 2 pixels on a 4 x 2 plane: pixel (3,1) has u = -2 + 4(3.5)/4 = 1.5 and
     * v = -1 + 2(1.5)/2 = 0.5: the direction is (1.5, 0.5, -1) / sqrt(3.5). */
    CameraSpec s = {.view = vec3(0, 0, -1), .focal = 1, .width = 4, .height = 2, .nx = 4, .ny = 2};
    Camera c = camera_make(&s);
    Ray r = camera_ray(&c, 3 + 0.5, 1 + 0.5);
    double k = 1 / sqrt(3.5);
    ck_assert_vec3_near(r.dir, vec3(1.5 * k, 0.5 * k, -k), 1e-15);
}
END_TEST

START_TEST(ray_of_the_centre_pixel)
{
    /* The middle pixel of 3 x 3 looks straight along D, whatever D is. */
    CameraSpec s = spec(vec3(0, 0, 0), vec3(1, 2, -2), 3, 3);
    Camera c = camera_make(&s);
    Ray r = camera_ray(&c, 1 + 0.5, 1 + 0.5);
    ck_assert_vec3_near(r.dir, vec3(1.0 / 3, 2.0 / 3, -2.0 / 3), 1e-15);
}
END_TEST

START_TEST(ray_through_the_image_corner)
{
    /* Image point (0,0) is the plane's corner (l, b) at distance d: (-1, -1, -2) / sqrt 6
     * for d = 2. Rays are unit length. */
    CameraSpec s = {.view = vec3(0, 0, -1), .focal = 2, .width = 2, .height = 2, .nx = 8, .ny = 8};
    Camera c = camera_make(&s);
    Ray r = camera_ray(&c, 0, 0);
    double k = 1 / sqrt(6);
    ck_assert_vec3_near(r.dir, vec3(-k, -k, -2 * k), 1e-15);
    ck_assert_double_eq_tol(vec3_length(r.dir), 1, 1e-15);
}
END_TEST

/* The camera's tests. */
static Suite *camera_suite(void)
{
    Suite *s = suite_create("camera");
    TCase *frame = tcase_create("frame");
    tcase_add_test(frame, frame_looking_down_minus_z);
    tcase_add_test(frame, frame_looking_along_plus_x);
    tcase_add_test(frame, frame_tilted_down);
    tcase_add_test(frame, frame_does_not_depend_on_the_length_of_d);
    tcase_add_test(frame, frame_looking_straight_down);
    tcase_add_test(frame, frame_looking_straight_up);
    tcase_add_test(frame, image_plane_is_centred);
    suite_add_tcase(s, frame);
    TCase *rays = tcase_create("rays");
    tcase_add_test(rays, ray_of_the_bottom_left_pixel);
    tcase_add_test(rays, ray_of_the_top_right_pixel);
    tcase_add_test(rays, ray_of_the_centre_pixel);
    tcase_add_test(rays, ray_through_the_image_corner);
    suite_add_tcase(s, rays);
    return s;
}

TEST_MAIN(camera_suite)
