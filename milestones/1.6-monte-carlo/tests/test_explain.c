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

/* Returns what raytra with arguments prints (its first MiB, to free), failing, in words,
 * unless it exits with status 0. */
static char *run_ok(const char *arguments)
{
    int status;
    char *text = testing_run(arguments, &status);
    ck_assert_msg(WIFEXITED(status) && WEXITSTATUS(status) == 0,
                  "raytra -q %s %s %d, where it must succeed; it printed:\n%s", arguments,
                  WIFEXITED(status) ? "exits with status" : "is killed by signal",
                  WIFEXITED(status) ? WEXITSTATUS(status) : WTERMSIG(status), text);
    return text;
}

/* Tells whether colours a and b agree to within tol in every component (never if NaN). */
static bool color_near(Color a, Color b, double tol)
{
    return fabs(a.r - b.r) <= tol && fabs(a.g - b.g) <= tol && fabs(a.b - b.b) <= tol;
}

/* Reads the three numbers after the last occurrence of what in text, "(r, g, b)". */
static Color color_after(const char *text, const char *what)
{
    const char *at = NULL;
    for (const char *p = strstr(text, what); p != NULL; p = strstr(p + 1, what))
        at = p;
    ck_assert_msg(at != NULL, "'%s' missing from:\n%s", what, text);
    Color c;
    ck_assert_msg(sscanf(at + strlen(what), "(%lf, %lf, %lf)", &c.r, &c.g, &c.b) == 3,
                  "no colour (r, g, b) after '%s' in:\n%s", what, text);
    return c;
}

/* The edge of exercise 1.6.1: a white triangle, lit by an ambient light of 1, covers
 * the plane z = 0 left of x = -0.5; each of the 4 x 4 pixels sees 1 unit of it, so the
 * edge runs down the middle of column 1. */
static void write_edge(void)
{
    FILE *f = fopen("edge.scn", "w");
    ck_assert_msg(f != NULL, "cannot write edge.scn in the test's folder");
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
        char *text = run_ok(arguments);
        /* Only sample k is traced: one camera ray. */
        char header[96];
        snprintf(header, sizeof header,
                 "sample %d of 0 to 3: in sub-square %d from the left, %d "
                 "from the bottom",
                 k, k % 2, k / 2);
        ck_assert_msg(strstr(text, header) != NULL, "'%s' missing from:\n%s", header, text);
        const char *camera = strstr(text, "camera ray");
        ck_assert_msg(camera != NULL && strstr(camera + 1, "camera ray") == NULL,
                      "--trace-pixel 1,1@%d traces %s camera ray, not one: sample %d alone:\n%s", k,
                      camera == NULL ? "no" : "more than one", k, text);
        double x = NAN, y = NAN;
        const char *point = strstr(text, "bottom, at image point (");
        ck_assert_msg(point != NULL, "'bottom, at image point (' missing from:\n%s", text);
        ck_assert_msg(sscanf(point, "bottom, at image point (%lf, %lf)", &x, &y) == 2,
                      "no image point (x, y) after 'bottom, at image point' in:\n%s", text);
        /* Pixel (1, 1) from the top is i = 1, j = 2: its sub-square k is [1 + (k % 2)/2,
         * 1 + (k % 2 + 1)/2) x [2 + (k / 2)/2, 2 + (k / 2 + 1)/2). */
        bool in_column = x >= 1 + 0.5 * (k % 2) && x < 1.5 + 0.5 * (k % 2);
        bool in_row = y >= 2 + 0.5 * (k / 2) && y < 2.5 + 0.5 * (k / 2);
        ck_assert_msg(in_column && in_row,
                      "sample %d of pixel i = 1, j = 2 (1,1 from the top) at P = 2 goes through "
                      "image point (%g, %g), outside its sub-square [%g, %g) x [%g, %g): "
                      "montecarlo_point puts ray k in sub-square k of the pixel, k %% P from the "
                      "left and k / P from the bottom",
                      k, x, y, 1 + 0.5 * (k % 2), 1.5 + 0.5 * (k % 2), 2 + 0.5 * (k / 2),
                      2.5 + 0.5 * (k / 2));
        char label[32];
        snprintf(label, sizeof label, "sample %d: colour ", k);
        double want = k % 2 == 0 ? 1 : 0;
        Color got = color_after(text, label);
        ck_assert_msg(color_near(got, color(want, want, want), 0),
                      "sample %d of pixel 1,1 at P = 2, in the %s half of the pixel, has colour "
                      "(%g, %g, %g), not %g, the colour of %s",
                      k, k % 2 == 0 ? "left" : "right", got.r, got.g, got.b, want,
                      k % 2 == 0 ? "the white triangle" : "the black background");
        ck_assert_msg(strstr(text, k % 2 == 0 ? "hits triangle 0" : "hits nothing") != NULL,
                      "sample %d of pixel 1,1 at P = 2, in the %s half of the pixel, does not "
                      "show '%s':\n%s",
                      k, k % 2 == 0 ? "left" : "right",
                      k % 2 == 0 ? "hits triangle 0" : "hits nothing", text);
        free(text);
    }
    char *text = run_ok("edge.scn --samples 2 --trace-pixel 1,1");
    Color pixel = color_after(text, "\ncolour ");
    ck_assert_msg(color_near(pixel, color(0.5, 0.5, 0.5), 0),
                  "pixel 1,1 at P = 2 is (%g, %g, %g), not 0.5, the mean of its 4 samples, two "
                  "on the triangle (1) and two off it (0): montecarlo_pixel averages the P x P "
                  "samples, 1/P^2 each",
                  pixel.r, pixel.g, pixel.b);
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
        char *text = run_ok(line);
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
    char *text = run_ok(line);
    Color pixel = color_after(text, "\ncolour ");
    free(text);
    ck_assert_msg(color_near(mean, pixel, 1e-8),
                  "the mean of the 9 samples of pixel 13,21 (P = 3) traced alone, (%.9g, %.9g, "
                  "%.9g), is not the pixel of the whole trace, (%.9g, %.9g, %.9g): "
                  "montecarlo_pixel is the mean of its P x P samples, each as montecarlo_sample "
                  "traces it",
                  mean.r, mean.g, mean.b, pixel.r, pixel.g, pixel.b);
    /* In the penumbra: some light arrives, but not all of it. */
    Color lit = mean_of_samples(arguments, "13,24", 9);
    ck_assert_msg(pixel.g > 0.1 && pixel.g < lit.g - 0.05,
                  "pixel 13,21 of soft-shadow.scn (--scale 0.25) is not in the red ball's "
                  "penumbra: its green is %g, not above 0.1 and 0.05 below the lit pixel 13,24's "
                  "%g; is the light sampled all over the square (area_point, "
                  "montecarlo_light_point)?",
                  pixel.g, lit.g);
    for (int threads = 1; threads <= 2; threads++) {
        snprintf(line, sizeof line, "%s -j %d out.pfm", arguments, threads);
        free(run_ok(line));
        Image img;
        Error err;
        ck_assert_msg(image_read_pfm(&img, "out.pfm", &err), "%s", err.text);
        Color rendered = image_get(&img, 13, 21);
        ck_assert_msg(color_near(rendered, mean, 1e-6),
                      "pixel 13,21 rendered on %d thread%s is (%.9g, %.9g, %.9g), not the mean of "
                      "its 9 samples traced alone, (%.9g, %.9g, %.9g)",
                      threads, threads == 1 ? "" : "s", rendered.r, rendered.g, rendered.b, mean.r,
                      mean.g, mean.b);
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
    char *a = run_ok(arguments);
    char again[1300];
    snprintf(again, sizeof again, "%s -j 2", arguments);
    char *b = run_ok(again);
    ck_assert_msg(
        strcmp(a, b) == 0,
        "--trace-pixel 17,27@13 traces otherwise on 1 and on 2 threads:\n%s\n-- and --\n%s", a, b);
    const char *where = "sample 13 of 0 to 15: in sub-square 1 from the left, 3 from the bottom";
    ck_assert_msg(strstr(a, where) != NULL,
                  "'%s' missing from the trace of --trace-pixel 17,27@13 at P = 4 (sample k is "
                  "in sub-square k %% P from the left, k / P from the bottom):\n%s",
                  where, a);
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
    ck_assert_msg(status_of("edge.scn --trace-pixel 3,1@0") == 0,
                  "--trace-pixel 3,1@0 is refused at P = 1, whose one sample is sample 0");
    ck_assert_msg(status_of("edge.scn --trace-pixel 3,1@1") == 2,
                  "--trace-pixel 3,1@1 is not refused at P = 1, which has sample 0 alone");
    ck_assert_msg(status_of("edge.scn --samples 4 --trace-pixel 3,1@15") == 0,
                  "--trace-pixel 3,1@15 is refused at P = 4, whose samples are 0 to 15");
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
