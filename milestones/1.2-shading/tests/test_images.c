/* test_images.c: images with known answers: a matte floor, and one plane in both conventions. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "camera.h"
#include "image.h"
#include "testing.h"

/* What scenes/lambert-floor.scn says: the floor y = 0, the light, kd and I. */
static const Vec3 light = {20, 40, -30};
static const Color intensity = {0.9, 0.8, 1.0};
static const Color kd = {0.6, 0.5, 0.4};

/* Renders scenes/name with the part's program into output and reads it back into img. */
static void render(const char *name, const char *output, Image *img)
{
    char command[2048];
    snprintf(command, sizeof command, "'%s' -q '%s/scenes/%s' %s", RAYTRA, TOP_DIR, name, output);
    ck_assert_int_eq(system(command), 0);
    Error err;
    ck_assert_msg(image_read_pfm(img, output, &err), "%s", err.text);
}

START_TEST(every_pixel_is_kd_I_cos_theta)
{
    char scene_path[512];
    snprintf(scene_path, sizeof scene_path, "%s/scenes/lambert-floor.scn", TOP_DIR);
    Image img;
    render("lambert-floor.scn", "lambert.pfm", &img);

    Scene scene;
    SceneLoadOptions opts = {0};
    ck_assert(scene_load(&scene, scene_path, &opts));
    Camera cam = camera_make(&scene.camera);
    int checked = 0;
    for (int j = 0; j < cam.ny; j += 7)
        for (int i = 0; i < cam.nx; i += 7) {
            /* Where the pixel's ray meets y = 0, solved here without plane_intersect. */
            Ray r = camera_ray(&cam, i + 0.5, j + 0.5);
            ck_assert(r.dir.y < 0);
            Vec3 p = ray_at(r, -r.origin.y / r.dir.y);
            Vec3 to_light = vec3_sub(light, p);
            double cos_theta = to_light.y / vec3_length(to_light);
            Color expected = color_scale(color_mul(kd, intensity), cos_theta);
            /* The render loop stores pixel (i, j) in row ny - 1 - j; PFM holds floats. */
            Color got = image_get(&img, i, cam.ny - 1 - j);
            ck_assert_color_near(got, expected, 1e-6);
            checked++;
        }
    ck_assert_int_eq(checked, 23 * 18);
    scene_free(&scene);
    image_free(&img);
}
END_TEST

START_TEST(both_plane_conventions_give_the_same_image)
{
    /* planes-lecture.scn writes p 0 1 0 20 (p.N + d = 0), planes-fall2016.scn p 0 1 0 -20
     * (p.N = d): the same floor. A directional light does not fall off, so the two
     * conventions must agree to the last bit. */
    Image lecture, fall2016;
    render("planes-lecture.scn", "lecture.pfm", &lecture);
    render("planes-fall2016.scn", "fall2016.pfm", &fall2016);
    ck_assert_int_eq(lecture.width, fall2016.width);
    ck_assert_int_eq(lecture.height, fall2016.height);
    ck_assert_mem_eq(lecture.pixels, fall2016.pixels,
                     sizeof(float) * 3 * (size_t)lecture.width * (size_t)lecture.height);
    image_free(&lecture);
    image_free(&fall2016);
}
END_TEST

/* The image tests. */
static Suite *images_suite(void)
{
    Suite *s = suite_create("images");
    TCase *tc = tcase_create("known answers");
    tcase_add_test(tc, every_pixel_is_kd_I_cos_theta);
    tcase_add_test(tc, both_plane_conventions_give_the_same_image);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(images_suite)
