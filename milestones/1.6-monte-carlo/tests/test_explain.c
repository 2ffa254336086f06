/* test_explain.c: --trace-pixel X,Y@SAMPLE: one sample's ray tree and colour, as the render has it.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "image.h"
#include "testing.h"

/* Returns the exit status of raytra with arguments, whose output is not needed. */
static int status_of(const char *arguments)
{
    int status;
    free(testing_run(arguments, &status));
    return WEXITSTATUS(status);
}

/* Reads the three numbers after the last occurrence of what in text, "(r, g, b)". */
static Color color_after(const char *text, const char *what)
{
    const char *at = NULL;
    for (const char *p = strstr(text, what); p != NULL; p = strstr(p + 1, what))
        at = p;
    ck_assert_msg(at != NULL, "'%s' missing from:\n%s", what, text);
    Color c;
    ck_assert_int_eq(sscanf(at + strlen(what), "(%lf, %lf, %lf)", &c.r, &c.g, &c.b), 3);
    return c;
}

/* The edge of exercise 1.6.1: a white triangle, lit by an ambient light of 1, covers
 * the plane z = 0 left of x = -0.5; each of the 4 x 4 pixels sees 1 unit of it, so the
 * edge runs down the middle of column 1. */
static void write_edge(void)
{
    FILE *f = fopen("edge.scn", "w");
    ck_assert_ptr_nonnull(f);
    fputs("c 0 0 10   0 0 -1   10   4 4   4 4\nl a 1 1 1\nm 1 1 1   0 0 0   1   0 0 0\n"
          "t -100 -100 0   -0.5 -100 0   -0.5 100 0\n",
          f);
    fclose(f);
}

/* With P = 2, samples 0 and 2 lie in the left half of the pixel (sub-squares 0 from the
 * left), on the white triangle: colour 1; samples 1 and 3 in the right half, on the black
 * background: 0. Whatever the random numbers, the pixel is exactly 1/2. */
START_TEST(each_sample_of_a_pixel_on_an_edge_by_hand)
{
    write_edge();
    for (int k = 0; k < 4; k++) {
        char arguments[128];
        snprintf(arguments, sizeof arguments, "edge.scn --samples 2 --trace-pixel 1,1@%d", k);
        int status;
        char *text = testing_run(arguments, &status);
        ck_assert_int_eq(status, 0);
        /* Only sample k is traced: one camera ray. */
        char header[96];
        snprintf(header, sizeof header,
                 "sample %d of 0 to 3: in sub-square %d from the left, %d "
                 "from the bottom",
                 k, k % 2, k / 2);
        ck_assert_msg(strstr(text, header) != NULL, "'%s' missing from:\n%s", header, text);
        const char *camera = strstr(text, "camera ray");
        ck_assert(camera != NULL && strstr(camera + 1, "camera ray") == NULL);
        double x, y;
        const char *point = strstr(text, "bottom, at image point (");
        ck_assert(point != NULL);
        ck_assert_int_eq(sscanf(point, "bottom, at image point (%lf, %lf)", &x, &y), 2);
        /* Pixel (1, 1) from the top is i = 1, j = 2: its sub-square k is [1 + (k % 2)/2,
         * 1 + (k % 2 + 1)/2) x [2 + (k / 2)/2, 2 + (k / 2 + 1)/2). */
        ck_assert(x >= 1 + 0.5 * (k % 2) && x < 1.5 + 0.5 * (k % 2));
        ck_assert(y >= 2 + 0.5 * (k / 2) && y < 2.5 + 0.5 * (k / 2));
        char label[32];
        snprintf(label, sizeof label, "sample %d: colour ", k);
        double want = k % 2 == 0 ? 1 : 0;
        ck_assert_color_near(color_after(text, label), color(want, want, want), 0);
        ck_assert(strstr(text, k % 2 == 0 ? "hits triangle 0" : "hits nothing") != NULL);
        free(text);
    }
    int status;
    char *text = testing_run("edge.scn --samples 2 --trace-pixel 1,1", &status);
    ck_assert_int_eq(status, 0);
    ck_assert_color_near(color_after(text, "\ncolour "), color(0.5, 0.5, 0.5), 0);
    free(text);
}
END_TEST

/* Returns the mean of the colours that --trace-pixel X,Y@k prints for each of the
 * pixel's count samples, with the given arguments before it. */
static Color mean_of_samples(const char *arguments, const char *pixel, int count)
{
    Color sum = color(0, 0, 0);
    for (int k = 0; k < count; k++) {
        char line[1024], label[32];
        snprintf(line, sizeof line, "%s --trace-pixel %s@%d", arguments, pixel, k);
        snprintf(label, sizeof label, "sample %d: colour ", k);
        int status;
        char *text = testing_run(line, &status);
        ck_assert_int_eq(status, 0);
        sum = color_add(sum, color_after(text, label));
        free(text);
    }
    return color_scale(sum, 1.0 / count);
}

/* On soft-shadow.scn, a pixel in the penumbra of the red ball (3 x 3 samples, 2 x 2
 * shadow rays each, random placement): the mean of the nine samples' colours, each
 * traced alone, is the pixel of the full trace and of the render. */
START_TEST(the_samples_traced_alone_make_the_pixel)
{
    char scene[1024];
    snprintf(scene, sizeof scene,
             "'%s/scenes/soft-shadow.scn' --scale 0.25 --seed 3 --samples 3 --light-samples 2",
             TOP_DIR);
    char arguments[1200];
    snprintf(arguments, sizeof arguments, "%s --sampling random", scene);
    /* Column 13, row 21 of 50 x 38: the ground in the red ball's penumbra. */
    Color mean = mean_of_samples(arguments, "13,21", 9);
    char line[1300];
    snprintf(line, sizeof line, "%s --trace-pixel 13,21", arguments);
    int status;
    char *text = testing_run(line, &status);
    ck_assert_int_eq(status, 0);
    Color pixel = color_after(text, "\ncolour ");
    free(text);
    ck_assert_color_near(mean, pixel, 1e-8);
    /* In the penumbra: some light arrives, but not all of it. */
    Color lit = mean_of_samples(arguments, "13,24", 9);
    ck_assert(pixel.g > 0.1 && pixel.g < lit.g - 0.05);
    for (int threads = 1; threads <= 2; threads++) {
        snprintf(line, sizeof line, "%s -j %d out.pfm", arguments, threads);
        free(testing_run(line, &status));
        ck_assert_int_eq(status, 0);
        Image img;
        Error err;
        ck_assert_msg(image_read_pfm(&img, "out.pfm", &err), "%s", err.text);
        ck_assert_color_near(image_get(&img, 13, 21), mean, 1e-6);
        image_free(&img);
    }
}
END_TEST

START_TEST(a_sample_traced_twice_and_on_more_threads_is_the_same)
{
    char arguments[1200];
    snprintf(arguments, sizeof arguments,
             "'%s/scenes/soft-shadow.scn' --scale 0.25 --samples 4 --trace-pixel 17,27@13",
             TOP_DIR);
    int status;
    char *a = testing_run(arguments, &status);
    ck_assert_int_eq(status, 0);
    char again[1300];
    snprintf(again, sizeof again, "%s -j 2", arguments);
    char *b = testing_run(again, &status);
    ck_assert_int_eq(status, 0);
    ck_assert_str_eq(a, b);
    ck_assert(strstr(a, "sample 13 of 0 to 15: in sub-square 1 from the left, 3 from the bottom") !=
              NULL);
    free(a);
    free(b);
}
END_TEST

START_TEST(bad_samples_are_usage_errors)
{
    write_edge();
    const char *bad[] = {"3,1@",   "3,1@x",  "3,1@-1", "3,1@4",
                         "3,1@1x", "3,1@@1", "3@1",    "3,1@99999999999999"};
    for (size_t k = 0; k < sizeof bad / sizeof *bad; k++) {
        char arguments[128];
        snprintf(arguments, sizeof arguments, "edge.scn --samples 2 --trace-pixel '%s'", bad[k]);
        ck_assert_msg(status_of(arguments) == 2, "--trace-pixel %s was not refused", bad[k]);
    }
    /* With P = 1 there is one sample, 0. */
    ck_assert_int_eq(status_of("edge.scn --trace-pixel 3,1@0"), 0);
    ck_assert_int_eq(status_of("edge.scn --trace-pixel 3,1@1"), 2);
    ck_assert_int_eq(status_of("edge.scn --samples 4 --trace-pixel 3,1@15"), 0);
}
END_TEST

/* The tests of --trace-pixel in part 1.6. */
static Suite *explain_suite(void)
{
    Suite *s = suite_create("explain");
    TCase *tc = tcase_create("trace-pixel");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, each_sample_of_a_pixel_on_an_edge_by_hand);
    tcase_add_test(tc, the_samples_traced_alone_make_the_pixel);
    tcase_add_test(tc, a_sample_traced_twice_and_on_more_threads_is_the_same);
    tcase_add_test(tc, bad_samples_are_usage_errors);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(explain_suite)
