/* test_images.c: whole renders: a sphere of index 1 vanishes under the exact Fresnel equations only. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "camera.h"
#include "image.h"
#include "testing.h"

/* The test scene: a floor, a wall, a red ball half behind where the glass ball will be,
 * an ambient light and, when lit, a point light; with_glass adds a sphere of index 1 and
 * no absorption, no colour of its own, in front. */
static const char *scene_text(bool with_glass, bool lit)
{
    static char text[1024];
    snprintf(text, sizeof text,
             "c 0 8 30  0 -0.2 -1  35  35 26.25  160 120\n"
             "%sl a 0.2 0.2 0.2\n"
             "m 0.6 0.6 0.6  0 0 0  1  0 0 0\np 0 1 0 0\np 0 0 1 30\n"
             "m 0.8 0.2 0.1  0.5 0.5 0.5  50  0 0 0\ns 4 5 -12  5\n"
             "%s",
             lit ? "l p 10 30 10  1 1 1\n" : "", with_glass ? "m 0 0 0  0 0 0  1  0 0 0  1  1 1 1\ns 0 6 -2  5\n" : "");
    return text;
}

/* Renders the scene (with or without the glass) with the part's program and options into img. */
static void render(bool with_glass, bool lit, const char *options, Image *img)
{
    FILE *f = fopen("invisible.scn", "w");
    ck_assert_ptr_nonnull(f);
    fputs(scene_text(with_glass, lit), f);
    fclose(f);
    char command[1024];
    snprintf(command, sizeof command, "'%s' -q %s invisible.scn out.pfm", RAYTRA, options);
    ck_assert_int_eq(system(command), 0);
    Error err;
    ck_assert_msg(image_read_pfm(img, "out.pfm", &err), "%s", err.text);
}

/* Returns the largest difference between the colours of pixel (i, row) of a and b. */
static double pixel_difference(const Image *a, const Image *b, int i, int row)
{
    Color p = image_get(a, i, row), q = image_get(b, i, row);
    return fmax(fabs(p.r - q.r), fmax(fabs(p.g - q.g), fabs(p.b - q.b)));
}

/* Returns how far the primary ray of pixel (i, j) passes from the glass ball's centre,
 * in units of its radius. */
static double pass_distance(const Camera *cam, int i, int j)
{
    Ray r = camera_ray(cam, i + 0.5, j + 0.5);
    Vec3 to_centre = vec3_sub(vec3(0, 6, -2), r.origin);
    Vec3 across = vec3_sub(to_centre, vec3_scale(r.dir, vec3_dot(to_centre, r.dir)));
    return vec3_length(across) / 5;
}

START_TEST(index_one_is_invisible_under_the_exact_equations)
{
    Image without, with;
    render(false, true, "", &without);
    render(true, true, "--fresnel exact", &with);
    CameraSpec spec = {.eye = {0, 8, 30}, .view = vec3_normalize(vec3(0, -0.2, -1)),
                       .focal = 35, .width = 35, .height = 26.25, .nx = 160, .ny = 120};
    Camera cam = camera_make(&spec);
    /* One pixel spans 35/160 units at 35 from the eye; the ball is 32 away: 0.2 units,
     * 0.04 radii. Only there may a grazing ray, nudged by the offsets, be different. */
    int inside = 0, differ = 0;
    for (int j = 0; j < 120; j++)
        for (int i = 0; i < 160; i++) {
            double pass = pass_distance(&cam, i, j);
            inside += pass < 1;
            double d = pixel_difference(&with, &without, i, 119 - j);
            /* The PFM holds floats: 1e-6 is a few of their steps at these values. */
            if (d > 1e-6) {
                differ++;
                ck_assert_msg(fabs(pass - 1) < 0.05, "pixel (%d, %d) differs by %g", i, j, d);
            }
        }
    ck_assert_int_gt(inside, 2000);
    ck_assert_int_le(differ, 10);
    image_free(&without);
    image_free(&with);
}
END_TEST

START_TEST(index_one_shows_a_rim_under_schlick)
{
    /* Schlick's R = R0 + (1 - R0)(1 - cos)^5 is not 0 at n = 1 (R0 = 0) but for head-on
     * rays: towards the rim, the ball reflects its surroundings. Without the point light,
     * so that its shadow (shadow rays keep 1 - R) does not change the rest. */
    Image without, with;
    render(false, false, "", &without);
    render(true, false, "--fresnel schlick", &with);
    CameraSpec spec = {.eye = {0, 8, 30}, .view = vec3_normalize(vec3(0, -0.2, -1)),
                       .focal = 35, .width = 35, .height = 26.25, .nx = 160, .ny = 120};
    Camera cam = camera_make(&spec);
    int rim = 0;
    for (int j = 0; j < 120; j++)
        for (int i = 0; i < 160; i++) {
            double pass = pass_distance(&cam, i, j);
            double d = pixel_difference(&with, &without, i, 119 - j);
            /* In the middle (cos > 0.95) R < 3e-7: no visible change. */
            if (pass < 0.3)
                ck_assert(d < 1e-6);
            /* Towards the rim (cos < 0.6, R > 0.01) it shows. */
            if (pass > 0.8 && pass < 0.97 && d > 1e-3)
                rim++;
            if (pass > 1.05)
                ck_assert(d < 1e-6);
        }
    ck_assert_int_gt(rim, 300);
    image_free(&without);
    image_free(&with);
}
END_TEST

START_TEST(a_bad_fresnel_model_is_refused)
{
    FILE *f = fopen("invisible.scn", "w");
    fputs(scene_text(true, true), f);
    fclose(f);
    char command[1024];
    snprintf(command, sizeof command, "'%s' -q --fresnel approximate invisible.scn out.png 2>err",
             RAYTRA);
    ck_assert_int_ne(system(command), 0);
    char text[512] = "";
    f = fopen("err", "r");
    size_t n = fread(text, 1, sizeof text - 1, f);
    text[n] = '\0';
    fclose(f);
    ck_assert_contains(text, "--fresnel takes schlick or exact, got 'approximate'");
    ck_assert_ptr_null(fopen("out.png", "r"));
}
END_TEST

START_TEST(trace_pixel_tells_the_glass)
{
    /* The centre pixel looks head-on through a glass ball of radius 2 (a = 0.5 per unit)
     * at a white wall: entering and leaving with R = R0 = 0.04, absorbed by 0.5^4. */
    FILE *f = fopen("glass.scn", "w");
    fputs("c 0 0 10  0 0 -1  1  1 1  3 3\nl a 1 1 1\n"
          "m 1 1 1  0 0 0  1  0 0 0\np 0 0 1 10\n"
          "m 0 0 0  0 0 0  1  0 0 0  1.5  0.5 0.5 0.5\ns 0 0 0 2\n",
          f);
    fclose(f);
    char command[1024];
    snprintf(command, sizeof command, "'%s' -q --trace-pixel 1,1 glass.scn > tree 2>&1", RAYTRA);
    ck_assert_int_eq(system(command), 0);
    static char text[1 << 16];
    f = fopen("tree", "r");
    size_t n = fread(text, 1, sizeof text - 1, f);
    text[n] = '\0';
    fclose(f);
    ck_assert_contains(text, "glass of index 1.5, entering it: refracted, R = 0.04\n");
    ck_assert_contains(text, "refracted ray from (");
    ck_assert_contains(text, "glass of index 1.5, leaving it: refracted, R = 0.04\n");
    ck_assert_contains(text, "times a^t, absorbed inside = (0.0625, 0.0625, 0.0625)");
    /* The reflected ray off the front goes back past the camera into the background. */
    ck_assert_contains(text, "hits nothing: the black background");
    /* --trace-pixel writes no image: an output it could not write (in a missing folder,
     * of an unknown format, the scene itself) is no reason to refuse, and is left alone. */
    ck_assert_int_eq(system("cp glass.scn glass.orig"), 0);
    const char *outputs[] = {"no-such-folder/out.png", "out.jpg", "glass.scn"};
    for (int k = 0; k < 3; k++) {
        snprintf(command, sizeof command,
                 "'%s' -q --trace-pixel 1,1 glass.scn %s > again 2>&1 && cmp -s tree again && "
                 "cmp -s glass.scn glass.orig",
                 RAYTRA, outputs[k]);
        ck_assert_msg(system(command) == 0, "with the output %s", outputs[k]);
    }
}
END_TEST

START_TEST(trace_pixel_tells_a_shadow_ray_through_glass)
{
    /* scenes/trace-glass-shadow.scn, worked out by hand in its comment: the shadow ray
     * from the wall meets the glass ball's front, crosses it to its back, goes on to the
     * light, and (1 - 0.04)^2 0.5^2 of the light gets through. */
    char command[1024];
    snprintf(command, sizeof command,
             "'%s' -q --trace-pixel 1,1 '%s/scenes/trace-glass-shadow.scn' > tree 2>&1", RAYTRA,
             TOP_DIR);
    ck_assert_int_eq(system(command), 0);
    static char text[1 << 16];
    FILE *f = fopen("tree", "r");
    size_t n = fread(text, 1, sizeof text - 1, f);
    text[n] = '\0';
    fclose(f);
    /* In this order, each stretch of the shadow ray with what it meets. */
    const char *expected[] = {
        "\n    shadow ray from (0, 0, ",
        "trace-glass-shadow.scn:17) at t = 6.07106781\n",
        "front face",
        ("\n    shadow ray on through glass (crossing 1) from (4.29289, 0, 4.29289) along "
         "(0.707107, 0, 0.707107)"),
        "trace-glass-shadow.scn:17) at t = 2\n",
        "back face",
        "\n    shadow ray on through glass (crossing 2) from (5.70711, 0, 5.70711)",
        "\n      reaches the light",
        "\n    what gets through = (0.2304, 0.2304, 0.2304)\n",
        "\n    adds = (0.162917, 0.162917, 0.162917)\n",
    };
    const char *at = text;
    for (size_t k = 0; k < sizeof expected / sizeof *expected; k++) {
        const char *found = strstr(at, expected[k]);
        ck_assert_msg(found != NULL, "'%s' missing, or out of order, in:\n%s", expected[k], text);
        at = found + strlen(expected[k]);
    }
}
END_TEST

START_TEST(an_open_glass_mesh_is_warned_about_once)
{
    /* Two glass triangles sharing one edge: four edges belong to one triangle only. */
    FILE *f = fopen("open.scn", "w");
    fputs("c 0 0 10  0 0 -1  1  1 1  3 3\nl a 1 1 1\n"
          "m 0 0 0  0 0 0  1  0 0 0  1.5\n"
          "t -1 -1 0  1 -1 0  1 1 0\nt -1 -1 0  1 1 0  -1 1 0\n",
          f);
    fclose(f);
    char command[1024];
    snprintf(command, sizeof command, "'%s' -q open.scn out.png 2> err", RAYTRA);
    ck_assert_int_eq(system(command), 0);
    static char text[4096];
    f = fopen("err", "r");
    size_t n = fread(text, 1, sizeof text - 1, f);
    text[n] = '\0';
    fclose(f);
    ck_assert_contains(text, "open.scn: glass triangles are not closed: 4 edge(s)");
    ck_assert_ptr_null(strstr(strstr(text, "not closed") + 1, "not closed"));
}
END_TEST

START_TEST(a_mirror_of_glass_ends)
{
    /* Three balls of glass under mirror coatings (k_m 0, 0.5, 0.9) that see one another:
     * when each hit carried 1 + k_m of its light, --min-weight never pruned and the rays
     * of a pixel grew as 2^depth (this render never ended); with the glass taking
     * 1 - max(k_m), the children of a ray weigh no more than it does. */
    char command[1024];
    snprintf(command, sizeof command,
             "'%s' -j 2 --scale 0.25 '%s/scenes/glass-mirror.scn' out.png 2> err", RAYTRA,
             TOP_DIR);
    ck_assert_int_eq(system(command), 0);
    static char text[4096];
    FILE *f = fopen("err", "r");
    size_t n = fread(text, 1, sizeof text - 1, f);
    text[n] = '\0';
    fclose(f);
    unsigned long long rays = 0;
    const char *with = strstr(text, " threads: ");
    ck_assert_msg(with != NULL && sscanf(with, " threads: %llu rays", &rays) == 1, "%s", text);
    /* 60 x 45 pixels: about 215 rays a pixel (1.2 million a pixel would be 2^20). */
    ck_assert_uint_lt(rays, 1000ULL * 60 * 45);
}
END_TEST

/* The image tests. */
static Suite *images_suite(void)
{
    Suite *s = suite_create("images");
    TCase *tc = tcase_create("renders");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, index_one_is_invisible_under_the_exact_equations);
    tcase_add_test(tc, index_one_shows_a_rim_under_schlick);
    tcase_add_test(tc, a_bad_fresnel_model_is_refused);
    tcase_add_test(tc, trace_pixel_tells_the_glass);
    tcase_add_test(tc, trace_pixel_tells_a_shadow_ray_through_glass);
    tcase_add_test(tc, an_open_glass_mesh_is_warned_about_once);
    tcase_add_test(tc, a_mirror_of_glass_ends);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(images_suite)
