/* test_explain.c: raytra --trace-pixel and --view on a scene worked out by hand. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "image.h"
#include "testing.h"

/* Runs raytra with options on scene (from the top of the repository); returns what it
 * printed on standard output, to free, and its exit status in *status. */
static char *run(const char *options, const char *scene, int *status)
{
    char arguments[4096];
    snprintf(arguments, sizeof arguments, "%s '%s/scenes/%s'", options, TOP_DIR, scene);
    return testing_run(arguments, status);
}

START_TEST(the_centre_pixel_by_hand)
{
    int status;
    char *text = run("--trace-pixel 1,1", "trace-pixel.scn", &status);
    ck_assert_int_eq(status, 0);
    const char *expected[] = {
        "pixel 1,1 of 3 x 3",
        "camera ray from (0, 0, 0) along (0, 0, -1)",
        "  hits sphere 0 (",
        "trace-pixel.scn:18) at t = 4\n",
        "    point (0, 0, -4), normal (0, 0, 1), front face",
        "  ambient, kd (.) ambient light = (0.05, 0.025, 0.01)",
        "  light 0, point (",
        "    towards it (0, 0, 1), arriving (1, 1, 1)",
        "    diffuse = (0.5, 0.25, 0.1)",
        "    specular = (0.2, 0.2, 0.2)",
        "    adds = (0.7, 0.45, 0.3)",
        "  light 1, directional (",
        "    behind the surface",
        "  light 2, point (",
        "    shadow ray from (",
        "      hits sphere 1 (",
        "trace-pixel.scn:20)",
        "    in shadow",
        "  radiance = (0.75, 0.475, 0.31)",
        "colour (0.75, 0.475, 0.31)",
        "in a PNG (sRGB): (225, 183, 151)",
    };
    for (size_t k = 0; k < sizeof expected / sizeof *expected; k++)
        ck_assert_msg(strstr(text, expected[k]) != NULL, "'%s' missing from:\n%s", expected[k],
                      text);
    free(text);
}
END_TEST

START_TEST(pixels_outside_the_image_are_refused)
{
    int status;
    free(run("--trace-pixel 3,0", "trace-pixel.scn", &status));
    ck_assert_int_eq(WEXITSTATUS(status), 2);
    free(run("--trace-pixel 1", "trace-pixel.scn", &status));
    ck_assert_int_eq(WEXITSTATUS(status), 2);
    free(run("--trace-pixel -1,0", "trace-pixel.scn", &status));
    ck_assert_int_ne(WEXITSTATUS(status), 0);
}
END_TEST

/* Renders trace-pixel.scn in view name to a PFM and returns its centre pixel, the only
 * one whose ray meets a surface. */
static Color view_centre(const char *name)
{
    char options[64];
    snprintf(options, sizeof options, "--view %s -o view.pfm", name);
    int status;
    free(run(options, "trace-pixel.scn", &status));
    ck_assert_int_eq(status, 0);
    Image img;
    Error err;
    ck_assert_msg(image_read_pfm(&img, "view.pfm", &err), "%s", err.text);
    Color c = image_get(&img, 1, 1);
    ck_assert_color_near(image_get(&img, 0, 0), color(0, 0, 0), 0);
    image_free(&img);
    return c;
}

START_TEST(views_of_the_centre_pixel_by_hand)
{
    /* The normal (0, 0, 1), each component mapped from [-1, 1] to [0, 1]. */
    ck_assert_color_near(view_centre("normal"), color(0.5, 0.5, 1), 1e-7);
    /* t = 4 is the median depth of the hits (the only one): half grey. */
    ck_assert_color_near(view_centre("depth"), color(0.5, 0.5, 0.5), 1e-7);
    ck_assert_color_near(view_centre("material"), color(0.5, 0.25, 0.1), 1e-7);
    /* One light of three reaches the point: a third of the heat scale, pure red. */
    ck_assert_color_near(view_centre("light-count"), color(1, 0, 0), 1e-7);
    int status;
    free(run("--view nope -o x.pfm", "trace-pixel.scn", &status));
    ck_assert_int_eq(WEXITSTATUS(status), 2);
    free(run("--view box-tests -o x.pfm", "trace-pixel.scn", &status));
    ck_assert_int_eq(WEXITSTATUS(status), 2);
}
END_TEST

/* The tests of --trace-pixel and --view. */
static Suite *explain_suite(void)
{
    Suite *s = suite_create("explain");
    TCase *tc = tcase_create("trace-pixel");
    tcase_add_test(tc, the_centre_pixel_by_hand);
    tcase_add_test(tc, pixels_outside_the_image_are_refused);
    tcase_add_test(tc, views_of_the_centre_pixel_by_hand);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(explain_suite)
