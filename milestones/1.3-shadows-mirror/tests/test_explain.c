/* test_explain.c: raytra --trace-pixel on a scene whose ray tree is worked out by hand. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "testing.h"

/* Runs raytra with options on scene (from the top of the repository); returns what it
 * printed on standard output, to free, and its exit status in *status. */
static char *run(const char *options, const char *scene, int *status)
{
    char command[4096];
    snprintf(command, sizeof command, "'%s' -q %s '%s/scenes/%s' 2>/dev/null", RAYTRA, options,
             TOP_DIR, scene);
    FILE *p = popen(command, "r");
    ck_assert_ptr_nonnull(p);
    char *text = calloc(1, 1 << 16);
    size_t used = fread(text, 1, (1 << 16) - 1, p);
    text[used] = '\0';
    *status = pclose(p);
    return text;
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
        "towards it (0, 0, 1), arriving (1, 1, 1)",
        "    diffuse = (0.5, 0.25, 0.1)",
        "    specular = (0.2, 0.2, 0.2)",
        "  light 1: behind the surface",
        "  light 2: in shadow",
        "    shadow ray from (",
        "      hits sphere 1 (",
        "trace-pixel.scn:20)",
        "  direct light = (0.75, 0.475, 0.31)",
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

/* The tests of --trace-pixel. */
static Suite *explain_suite(void)
{
    Suite *s = suite_create("explain");
    TCase *tc = tcase_create("trace-pixel");
    tcase_add_test(tc, the_centre_pixel_by_hand);
    tcase_add_test(tc, pixels_outside_the_image_are_refused);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(explain_suite)
