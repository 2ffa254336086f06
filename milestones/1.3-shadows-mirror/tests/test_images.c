/* test_images.c: images with analytic answers: a sphere's shadow, and no acne at any scale. */
#include <stdio.h>
#include <stdlib.h>

#include "camera.h"
#include "image.h"
#include "sphere.h"
#include "testing.h"

/* Renders the scene file at path with the part's program and options into img (PFM). */
static void render(const char *path, const char *options, Image *img)
{
    char command[2048];
    snprintf(command, sizeof command, "'%s' -q %s '%s' out.pfm", RAYTRA, options, path);
    ck_assert_int_eq(system(command), 0);
    Error err;
    ck_assert_msg(image_read_pfm(img, "out.pfm", &err), "%s", err.text);
}

/* Returns the distance from c to the part of the line p + s l with s > 0: the shadow
 * ray from p along l passes the sphere's centre at this distance. */
static double ray_distance(Vec3 p, Vec3 l, Vec3 c)
{
    double s = fmax(0, vec3_dot(vec3_sub(c, p), l));
    return vec3_length(vec3_sub(vec3_add_scaled(p, l, s), c));
}

START_TEST(shadow_of_a_sphere_under_a_point_light)
{
    char path[512];
    snprintf(path, sizeof path, "%s/scenes/shadow-sphere.scn", TOP_DIR);
    Scene scene;
    SceneLoadOptions opts = {0};
    ck_assert(scene_load(&scene, path, &opts));
    Image img;
    render(path, "", &img);
    const Sphere *ball = &scene.spheres[0];
    Vec3 light = scene.lights[0].position;
    Color kd = scene.materials[0].diffuse, ambient = scene.ambient;
    Camera cam = camera_make(&scene.camera);
    int lit = 0, shadowed = 0;
    for (int j = 0; j < cam.ny; j++)
        for (int i = 0; i < cam.nx; i++) {
            Ray r = camera_ray(&cam, i + 0.5, j + 0.5);
            double t;
            if (sphere_intersect(ball, r, 0, INFINITY, &t) || r.dir.y >= 0)
                continue; /* not the floor y = 0 */
            Vec3 p = ray_at(r, -r.origin.y / r.dir.y);
            Vec3 to_light = vec3_sub(light, p);
            double distance = vec3_length(to_light);
            Vec3 l = vec3_scale(to_light, 1 / distance);
            double pass = ray_distance(p, l, ball->center);
            Color got = image_get(&img, i, cam.ny - 1 - j);
            if (pass < 0.97 * ball->radius) {
                ck_assert_color_near(got, color_mul(kd, ambient), 1e-6);
                shadowed++;
            } else if (pass > 1.03 * ball->radius) {
                Color expected =
                    color_mul(kd, color_add(ambient, color_scale(color(1, 1, 1), l.y)));
                ck_assert_color_near(got, expected, 1e-6);
                lit++;
            }
        }
    ck_assert_int_gt(shadowed, 1000);
    ck_assert_int_gt(lit, 10000);
    scene_free(&scene);
    image_free(&img);
}
END_TEST

/* Writes the acne scene scaled by s, with the floor as a plane or as two huge triangles,
 * renders it and returns how many pixels differ from the analytic answer. */
static int acne_pixels(double s, bool triangles, const char *options)
{
    FILE *f = fopen("acne.scn", "w");
    fprintf(f, "c 0 %.17g %.17g   0 -0.3 -1   35   35 26.25   160 120\n", 15 * s, 60 * s);
    fprintf(f, "l d -1 -0.08 -0.3   1 1 1\nl a 0.1 0.1 0.1\nm 0.7 0.7 0.7 0 0 0 1 0 0 0\n");
    if (triangles)
        fprintf(f, "t %g 0 %g  %g 0 %g  %g 0 %g\nt %g 0 %g  %g 0 %g  %g 0 %g\n", -1e6 * s, 1e6 * s,
                1e6 * s, 1e6 * s, -1e6 * s, -1e6 * s, -1e6 * s, -1e6 * s, 1e6 * s, 1e6 * s, 1e6 * s,
                -1e6 * s);
    else
        fprintf(f, "p 0 1 0 0\n");
    fprintf(f, "m 0.3 0.5 0.8 0 0 0 1 0 0 0\ns 0 %.17g %.17g %.17g\n", 8 * s, -20 * s, 8 * s);
    fclose(f);
    Image img;
    render("acne.scn", options, &img);

    Scene scene;
    SceneLoadOptions opts = {.messages = stderr};
    ck_assert(scene_load(&scene, "acne.scn", &opts));
    Camera cam = camera_make(&scene.camera);
    const Sphere *ball = &scene.spheres[0];
    Vec3 l = vec3_neg(scene.lights[0].direction); /* towards the light */
    int wrong = 0, checked = 0;
    for (int j = 0; j < cam.ny; j++)
        for (int i = 0; i < cam.nx; i++) {
            Ray r = camera_ray(&cam, i + 0.5, j + 0.5);
            double t;
            Color expected;
            if (sphere_intersect(ball, r, 0, INFINITY, &t)) {
                /* The sphere: kd (ambient + max(0, n.l)), away from its terminator. */
                Vec3 n = vec3_scale(vec3_sub(ray_at(r, t), ball->center), 1 / ball->radius);
                double cos_theta = vec3_dot(n, l);
                if (fabs(cos_theta) < 0.02)
                    continue;
                expected = color_scale(scene.materials[1].diffuse, 0.1 + fmax(0, cos_theta));
            } else if (r.dir.y >= 0) {
                expected = color(0, 0, 0); /* above the horizon: the background */
            } else {
                /* The floor: kd (ambient + l.y), but only the ambient in the sphere's shadow. */
                Vec3 p = ray_at(r, -r.origin.y / r.dir.y);
                double pass = ray_distance(p, l, ball->center);
                if (fabs(pass - ball->radius) < 0.03 * ball->radius)
                    continue;
                expected =
                    color_scale(scene.materials[0].diffuse, 0.1 + (pass < ball->radius ? 0 : l.y));
            }
            Color got = image_get(&img, i, cam.ny - 1 - j);
            checked++;
            if (fabs(got.r - expected.r) > 1e-5 * (1 + expected.r) ||
                fabs(got.b - expected.b) > 1e-5 * (1 + expected.b))
                wrong++;
        }
    ck_assert_int_gt(checked, 15000);
    scene_free(&scene);
    image_free(&img);
    return wrong;
}

START_TEST(no_acne_at_any_scale)
{
    double scales[] = {1e-3, 1, 1e4};
    for (int k = 0; k < 3; k++) {
        ck_assert_int_eq(acne_pixels(scales[k], false, ""), 0);
        ck_assert_int_eq(acne_pixels(scales[k], true, ""), 0);
    }
}
END_TEST

START_TEST(the_acne_test_has_teeth)
{
    /* Without the offset, rounding puts about half the hit points under the surface and
     * their shadow rays hit it: many pixels go dark. */
    ck_assert_int_gt(acne_pixels(1, false, "--ray-offset 0"), 1000);
}
END_TEST

/* The image tests. */
static Suite *images_suite(void)
{
    Suite *s = suite_create("images");
    TCase *tc = tcase_create("shadows");
    tcase_set_timeout(tc, 600);
    tcase_add_test(tc, shadow_of_a_sphere_under_a_point_light);
    tcase_add_test(tc, no_acne_at_any_scale);
    tcase_add_test(tc, the_acne_test_has_teeth);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(images_suite)
