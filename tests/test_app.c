/* test_app.c: the program every part builds, run with a pixel function of the test's own. */
#include <fcntl.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "app.h"
#include "image.h"
#include "image_read.h"
#include "testing.h"

/* Grey everywhere but pixel (1, 1) (column 1, row 1 from the bottom), which is NaN. */
static Color one_nan(const void *ctx, int i, int j, RayStats *stats)
{
    (void)ctx;
    stats->rays[RAY_PRIMARY]++;
    return i == 1 && j == 1 ? color(NAN, 0.5, 0.5) : color(0.25, 0.25, 0.25);
}

/* A part that draws one_nan. */
static const Program nan_program = {
    .cli = {"9.9-test", "testing the shared program", NULL},
    .features = ~0u,
    .pixel = one_nan,
};

/* Writes text to path. */
static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fputs(text, f);
    ck_assert_int_eq(fclose(f), 0);
}

/* Reads the first size - 1 bytes of path into buf, as a string. */
static void read_text(const char *path, char *buf, size_t size)
{
    FILE *f = fopen(path, "r");
    ck_assert_ptr_nonnull(f);
    size_t n = fread(buf, 1, size - 1, f);
    buf[n] = '\0';
    fclose(f);
}

/* Runs app_main on the words given (ended by NULL), with standard error going to the file
 * "err"; returns the exit status. */
static int run(const Program *program, ...)
{
    char *argv[16] = {"raytra"};
    int argc = 1;
    va_list ap;
    va_start(ap, program);
    for (char *a; (a = va_arg(ap, char *)) != NULL;)
        argv[argc++] = a;
    va_end(ap);
    fflush(stderr);
    int saved = dup(STDERR_FILENO);
    int fd = open("err", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ck_assert_int_ge(fd, 0);
    dup2(fd, STDERR_FILENO);
    close(fd);
    int status = app_main(program, argc, argv);
    fflush(stderr);
    dup2(saved, STDERR_FILENO);
    close(saved);
    return status;
}

/* A 4 x 3 image; nothing in it, as the test's pixel function draws what it likes. */
static const char small_scene[] = "c 0 0 0  0 0 -1  1 1 1  4 3\n";

START_TEST(a_nan_pixel_is_magenta_and_told)
{
    write_text("s.scn", small_scene);
    ck_assert_int_eq(run(&nan_program, "-q", "-j", "2", "s.scn", "out.pfm", NULL), 0);
    char err[2048];
    read_text("err", err, sizeof err);
    ck_assert_contains(err, "raytra: warning: 1 pixel came out NaN or infinite");
    /* Row 1 from the bottom of 3 is row 1 from the top. */
    ck_assert_contains(err, "the first is at column 1, row 1 from the top");
    Image img;
    Error e;
    ck_assert(image_read(&img, "out.pfm", &e));
    ck_assert_color_near(image_get(&img, 1, 1), color(1, 0, 1), 0);
    ck_assert_color_near(image_get(&img, 2, 1), color(0.25, 0.25, 0.25), 0);
    image_free(&img);
}
END_TEST

START_TEST(strict_fails_on_a_nan_pixel)
{
    write_text("s.scn", small_scene);
    ck_assert_int_eq(run(&nan_program, "-q", "--strict", "s.scn", "out.pfm", NULL), 1);
    char err[2048];
    read_text("err", err, sizeof err);
    ck_assert_contains(err, "raytra: error: 1 pixel came out NaN or infinite");
    /* The image is written all the same, so that the magenta pixel shows the bug. */
    ck_assert_int_eq(access("out.pfm", F_OK), 0);
}
END_TEST

/* A smooth gradient, beyond 1 in places, as a render gives. */
static Color gradient(const void *ctx, int i, int j, RayStats *stats)
{
    (void)ctx, (void)stats;
    return color(i / 3.0, j / 2.0 * 1.5, 0.3);
}

static const Program gradient_program = {
    .cli = {"9.9-test", "testing the shared program", NULL},
    .features = ~0u,
    .pixel = gradient,
};

/* Reads the whole of path into a buffer to free; its size in *size. */
static unsigned char *slurp(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    ck_assert_ptr_nonnull(f);
    unsigned char *data = malloc(1 << 16);
    *size = fread(data, 1, 1 << 16, f);
    fclose(f);
    return data;
}

START_TEST(png_from_the_exr_equals_the_png_of_the_render)
{
    write_text("s.scn", small_scene);
    ck_assert_int_eq(run(&gradient_program, "-q", "s.scn", "out.png", NULL), 0);
    ck_assert_int_eq(run(&gradient_program, "-q", "s.scn", "out.exr", NULL), 0);
    Image img;
    Error e;
    ck_assert_msg(image_read(&img, "out.exr", &e), "%s", e.text);
    ck_assert(image_write(&img, "via-exr.png", PNG_ENCODING_SRGB, &e));
    image_free(&img);
    size_t n1, n2;
    unsigned char *a = slurp("out.png", &n1), *b = slurp("via-exr.png", &n2);
    ck_assert_uint_eq(n1, n2);
    ck_assert_mem_eq(a, b, n1);
    free(a);
    free(b);
}
END_TEST

START_TEST(unknown_extension_lists_exr)
{
    write_text("s.scn", small_scene);
    ck_assert_int_eq(run(&gradient_program, "-q", "s.scn", "out.tiff", NULL), 2);
    char err[2048];
    read_text("err", err, sizeof err);
    ck_assert_contains(err,
                       "cannot write 'out.tiff': unknown image format (use .png, .pfm or .exr)");
}
END_TEST

/* A probe that meets a surface lit by one light and tested against two boxes everywhere. */
static void probe_everything(const void *ctx, int i, int j, Probe *probe)
{
    (void)ctx, (void)i, (void)j;
    *probe = (Probe){.hit = true,
                     .t = 1,
                     .normal = vec3(0, 0, 1),
                     .kd = color(1, 0, 0),
                     .lights_visible = 1,
                     .tests = 2};
}

START_TEST(a_view_needs_what_it_draws)
{
    /* A part draws the views of what it has, as it declares them (Program.views): light
     * counts where it has lights, box tests where it has boxes; it refuses the others,
     * saying what it lacks, rather than draw black under a legend that promises counts. */
    write_text("s.scn", "c 0 0 0  0 0 -1  1 1 1  4 3\nl p 0 1 0  1 1 1\n");
    static const struct {
        unsigned views;
        const char *view, *refusal;
    } cases[] = {
        {0, "normal", NULL},
        {0, "material", NULL},
        {0, "light-count", "lights to count"},
        {0, "box-tests", "bounding boxes"},
        {1u << VIEW_LIGHT_COUNT, "light-count", NULL},
        {1u << VIEW_LIGHT_COUNT, "box-tests", "bounding boxes"},
        {1u << VIEW_LIGHT_COUNT | 1u << VIEW_BOX_TESTS, "box-tests", NULL},
    };
    for (size_t k = 0; k < sizeof cases / sizeof *cases; k++) {
        Program program = {.cli = {"9.9-test", "testing views", NULL},
                           .features = ~0u,
                           .pixel = one_nan,
                           .probe = probe_everything,
                           .views = cases[k].views};
        int status = run(&program, "--view", cases[k].view, "s.scn", "out.pfm", NULL);
        char err[2048], expected[256];
        read_text("err", err, sizeof err);
        if (cases[k].refusal == NULL) {
            ck_assert_msg(status == 0, "--view %s: %s", cases[k].view, err);
            continue;
        }
        snprintf(expected, sizeof expected,
                 "raytra: part 9.9-test cannot draw the view '%s': it has no %s yet (a later "
                 "part of the course draws it)\n",
                 cases[k].view, cases[k].refusal);
        ck_assert_int_eq(status, 2);
        ck_assert_str_eq(err, expected);
    }
}
END_TEST

/* The shared program's tests. */
static Suite *app_suite(void)
{
    Suite *s = suite_create("app");
    TCase *tc = tcase_create("nonfinite");
    tcase_add_test(tc, a_nan_pixel_is_magenta_and_told);
    tcase_add_test(tc, strict_fails_on_a_nan_pixel);
    suite_add_tcase(s, tc);
    tc = tcase_create("formats");
    tcase_add_test(tc, png_from_the_exr_equals_the_png_of_the_render);
    tcase_add_test(tc, unknown_extension_lists_exr);
    suite_add_tcase(s, tc);
    tc = tcase_create("views");
    tcase_add_test(tc, a_view_needs_what_it_draws);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(app_suite)
