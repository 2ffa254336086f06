/* test_silhouette.c: every pixel of the sphere scenes against the exact silhouettes. */
#include <stdio.h>

#include "camera.h"
#include "sphere.h"
#include "testing.h"

/* Tells (analytically) whether the ray from e along unit d meets sphere s at t > 0:
 * from outside, exactly when d lies in the cone around c = O - e of half-angle
 * asin(R / |c|), i.e. d.c > 0 and (d.c)^2 >= |c|^2 - R^2; from inside, always.
 * *margin is how far the pixel is from the cone's edge, to skip edge pixels. */
static bool inside_cone(const Sphere *s, Vec3 e, Vec3 d, double *margin)
{
    Vec3 c = vec3_sub(s->center, e);
    double cc = vec3_dot(c, c), rr = s->radius * s->radius, dc = vec3_dot(d, c);
    *margin = fabs(dc * dc - (cc - rr)) / cc;
    if (cc < rr)
        return true;
    return dc > 0 && dc * dc >= cc - rr;
}

/* Loads scenes/name of the repository into scene. */
static void load_scene(const char *name, Scene *scene)
{
    char path[512];
    snprintf(path, sizeof path, "%s/scenes/%s", TOP_DIR, name);
    SceneLoadOptions opts = {0};
    ck_assert_msg(scene_load(scene, path, &opts), "cannot load %s", path);
}

/* Checks every pixel of a scene file of spheres; returns the number of pixels hit. */
static long check_scene(const char *name)
{
    Scene scene;
    load_scene(name, &scene);
    Camera cam = camera_make(&scene.camera);
    long hits = 0, checked = 0;
    for (int j = 0; j < cam.ny; j++)
        for (int i = 0; i < cam.nx; i++) {
            Ray r = camera_ray(&cam, i + 0.5, j + 0.5);
            for (int k = 0; k < scene.sphere_count; k++) {
                const Sphere *s = &scene.spheres[k];
                double margin, t;
                bool expected = inside_cone(s, r.origin, r.dir, &margin);
                if (margin < 1e-9)
                    continue; /* too close to the silhouette to call */
                checked++;
                bool hit = sphere_intersect(s, r, 0, INFINITY, &t);
                ck_assert_msg(hit == expected, "%s: pixel (%d, %d), sphere %d: hit %d, expected %d",
                              name, i, j, k, hit, expected);
                hits += hit;
            }
        }
    ck_assert_int_gt(checked, (long)cam.nx * cam.ny * scene.sphere_count * 99 / 100);
    scene_free(&scene);
    return hits;
}

START_TEST(spheres_three)
{
    ck_assert_int_gt(check_scene("spheres-three.scn"), 1000);
}
END_TEST

START_TEST(spheres_behind_camera_are_invisible)
{
    ck_assert_int_gt(check_scene("spheres-behind-camera.scn"), 100);
}
END_TEST

START_TEST(camera_straight_down)
{
    ck_assert_int_gt(check_scene("camera-straight-down.scn"), 100);
}
END_TEST

START_TEST(wide_angle_grid)
{
    ck_assert_int_gt(check_scene("spheres-grid-wide.scn"), 1000);
}
END_TEST

START_TEST(straight_down_puts_minus_z_at_the_top)
{
    /* The large sphere at (0, 0, -60) seen from (0, 200, 0) straight down lies in
     * the direction (0, -200, -60): image up is -z, so it projects above the centre,
     * at v = d * 60/200 = 10.5 mm, i.e. pixel row j = 120 + 10.5 / 35 * 240 = 192. */
    Scene scene;
    load_scene("camera-straight-down.scn", &scene);
    Camera cam = camera_make(&scene.camera);
    double t;
    Ray r = camera_ray(&cam, 120, 192);
    ck_assert(sphere_intersect(&scene.spheres[1], r, 0, INFINITY, &t));
    r = camera_ray(&cam, 120, 48);
    ck_assert(!sphere_intersect(&scene.spheres[1], r, 0, INFINITY, &t));
    scene_free(&scene);
}
END_TEST

/* The silhouette tests. */
static Suite *silhouette_suite(void)
{
    Suite *s = suite_create("silhouette");
    TCase *tc = tcase_create("scenes");
    tcase_add_test(tc, spheres_three);
    tcase_add_test(tc, spheres_behind_camera_are_invisible);
    tcase_add_test(tc, camera_straight_down);
    tcase_add_test(tc, wide_angle_grid);
    tcase_add_test(tc, straight_down_puts_minus_z_at_the_top);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(silhouette_suite)
