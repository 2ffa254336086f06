/* test_render.c: the render loop: pixels, thread counts, counts, NaN and overflow, stop. */
#include <float.h>
#include <signal.h>
#include <stdatomic.h>
#include <string.h>
#include <time.h>

#include "progress.h"
#include "render.h"
#include "stop.h"
#include "testing.h"

/* A colour that encodes the pixel's coordinates, with a little arithmetic per pixel. */
static Color coordinates(const void *ctx, int i, int j, RayStats *stats)
{
    (void)ctx;
    stats->rays[RAY_PRIMARY]++;
    stats->rays[RAY_SHADOW] += (unsigned)(i % 3);
    double wobble = sin(i * 0.37 + j * 1.91);
    return color(i, j, wobble);
}

/* Renders w x h pixels of fn with the given number of threads. */
static RenderResult render(Image *img, int w, int h, PixelFn fn, int threads)
{
    ck_assert(image_init(img, w, h));
    RenderJob job = {.pixel = fn, .threads = threads};
    RenderResult r;
    render_image(img, &job, &r);
    return r;
}

START_TEST(row_zero_is_the_top)
{
    Image img;
    RenderResult r = render(&img, 5, 4, coordinates, 1);
    /* Pixel (i, j) counts j from the bottom: the top row holds j = 3. */
    ck_assert_color_near(image_get(&img, 0, 0), color(0, 3, sin(3 * 1.91)), 1e-6);
    ck_assert_color_near(image_get(&img, 4, 3), color(4, 0, sin(4 * 0.37)), 1e-6);
    ck_assert_int_eq(r.stats.rays[RAY_PRIMARY], 20);
    /* i % 3 summed over i = 0..4 is 0+1+2+0+1 = 4, on each of the 4 rows. */
    ck_assert_int_eq(r.stats.rays[RAY_SHADOW], 16);
    ck_assert_int_eq(render_total_rays(&r.stats), 36);
    ck_assert(!r.stopped);
    image_free(&img);
}
END_TEST

START_TEST(same_image_whatever_the_thread_count)
{
    Image one, many;
    RenderResult r1 = render(&one, 97, 61, coordinates, 1);
    for (int threads = 2; threads <= 9; threads += 7) {
        RenderResult rn = render(&many, 97, 61, coordinates, threads);
        ck_assert_mem_eq(one.pixels, many.pixels, sizeof(float) * 3 * 97 * 61);
        ck_assert_int_eq(rn.stats.rays[RAY_PRIMARY], r1.stats.rays[RAY_PRIMARY]);
        ck_assert_int_eq(rn.stats.rays[RAY_SHADOW], r1.stats.rays[RAY_SHADOW]);
        image_free(&many);
    }
    image_free(&one);
}
END_TEST

/* NaN at two pixels, infinity at a third, and at a fourth a finite double too large for
 * the image's floats (1e39 > FLT_MAX = 3.4e38), which a float would hold as infinity. */
static Color some_bad(const void *ctx, int i, int j, RayStats *stats)
{
    (void)ctx, (void)stats;
    if ((i == 3 && j == 1) || (i == 1 && j == 2))
        return color(NAN, 0, 0);
    if (i == 0 && j == 0)
        return color(0, INFINITY, 0);
    if (i == 2 && j == 0)
        return color(0, 0, -1e39);
    return color(0.5, 0.5, 0.5);
}

START_TEST(nonfinite_pixels_are_magenta_and_counted)
{
    Image img;
    RenderResult r = render(&img, 4, 3, some_bad, 3);
    ck_assert_int_eq(r.nonfinite, 4);
    /* In reading order the first is (1, 2): row 0 from the top. */
    ck_assert_int_eq(r.first_nonfinite_x, 1);
    ck_assert_int_eq(r.first_nonfinite_y, 0);
    ck_assert_color_near(image_get(&img, 1, 0), color(1, 0, 1), 0);
    ck_assert_color_near(image_get(&img, 0, 2), color(1, 0, 1), 0);
    ck_assert_color_near(image_get(&img, 2, 2), color(1, 0, 1), 0);
    ck_assert_color_near(image_get(&img, 3, 1), color(1, 0, 1), 0);
    ck_assert_color_near(image_get(&img, 2, 1), color(0.5, 0.5, 0.5), 0);
    image_free(&img);
}
END_TEST

/* Colours at the very edge of the float range. */
static Color edge_of_float(const void *ctx, int i, int j, RayStats *stats)
{
    (void)ctx, (void)j, (void)stats;
    return i == 0 ? color(FLT_MAX, 0, 0) : color(0, -FLT_MAX, 1e-300);
}

START_TEST(the_largest_float_is_kept)
{
    Image img;
    RenderResult r = render(&img, 2, 1, edge_of_float, 1);
    ck_assert_int_eq(r.nonfinite, 0);
    ck_assert(image_get(&img, 0, 0).r == FLT_MAX);
    ck_assert(image_get(&img, 1, 0).g == -FLT_MAX);
    image_free(&img);
}
END_TEST

/* Asks to stop at the first pixel of the middle row. */
static Color stop_midway(const void *ctx, int i, int j, RayStats *stats)
{
    (void)ctx, (void)stats;
    if (i == 0 && j == 50)
        stop_request(SIGINT);
    return color(1, 1, 1);
}

START_TEST(a_stop_request_ends_the_render)
{
    Image img;
    RenderResult r = render(&img, 10, 100, stop_midway, 1);
    ck_assert(r.stopped);
    /* The worker finished its pixel within the grace: nothing was given up. */
    ck_assert(!r.abandoned);
    ck_assert(render_idle());
    ck_assert_int_eq(stop_signal(), SIGINT);
    /* With one thread, the rows after the stop were never rendered. */
    ck_assert_color_near(image_get(&img, 0, 99), color(0, 0, 0), 0);
    stop_reset();
    ck_assert(!stop_requested());
    image_free(&img);
}
END_TEST

/* Released by the test: until then a stuck pixel never ends. */
static atomic_bool release;

/* Sleeps a millisecond. */
static void nap(void)
{
    struct timespec ms = {0, 1000000};
    nanosleep(&ms, NULL);
}

/* A pixel that asks to stop and then takes as long as the test wants: a pixel that
 * costs minutes, as 1.6's at P = S = 64, or 1.5's before its energy split. */
static Color stuck(const void *ctx, int i, int j, RayStats *stats)
{
    (void)ctx, (void)i, (void)j, (void)stats;
    stop_request(SIGTERM);
    while (!atomic_load(&release))
        nap();
    return color(0, 0, 0);
}

/* Waits until the threads given up have ended, at most 10 s. */
static void wait_idle(void)
{
    for (int k = 0; k < 10000 && !render_idle(); k++)
        nap();
    ck_assert(render_idle());
}

START_TEST(a_stop_ends_the_wait_whatever_a_pixel_costs)
{
    Image img;
    ck_assert(image_init(&img, 4, 4));
    atomic_store(&release, false);
    RenderJob job = {.pixel = stuck, .threads = 2};
    RenderResult r;
    double start = clock_now();
    render_image(&img, &job, &r);
    double waited = clock_now() - start;
    /* The grace is half a second: the wait ends then, the pixels still running. */
    ck_assert_msg(waited >= 0.4 && waited < 5, "waited %g s", waited);
    ck_assert(r.stopped);
    ck_assert(r.abandoned);
    ck_assert(!render_idle());
    /* The workers given up finish their pixel, see the stop and free what they share;
     * the image must live until then. */
    atomic_store(&release, true);
    wait_idle();
    stop_reset();
    image_free(&img);
}
END_TEST

/* Uses about n kilobytes of stack, a kilobyte a call, as a deep path of rays does; returns
 * a number that depends on all of it, so that no call can be left out. */
static unsigned deep(int n)
{
    volatile unsigned char frame[1000];
    for (size_t k = 0; k < sizeof frame; k++)
        frame[k] = (unsigned char)(n + k);
    if (n == 0)
        return frame[7];
    return deep(n - 1) + frame[n % sizeof frame];
}

/* A pixel that needs 12 MiB of stack: more than a default thread gets (8 MiB, from
 * `ulimit -s`), less than a render thread's 16. */
static Color deep_pixel(const void *ctx, int i, int j, RayStats *stats)
{
    (void)ctx, (void)i, (void)j, (void)stats;
    return color(deep(12 * 1024) > 0, 0, 0);
}

START_TEST(render_threads_have_a_deep_stack)
{
    Image img;
    RenderResult r = render(&img, 2, 1, deep_pixel, 2);
    ck_assert(!r.stopped);
    ck_assert_color_near(image_get(&img, 1, 0), color(1, 0, 0), 0);
    image_free(&img);
}
END_TEST

/* What render_call's function saw. */
typedef struct {
    bool stuck;
    unsigned depth_result;
} CallArg;

/* render_call's function: deep, or stuck after asking to stop. */
static void call_me(void *arg)
{
    CallArg *a = arg;
    if (a->stuck) {
        stop_request(SIGINT);
        while (!atomic_load(&release))
            nap();
        return;
    }
    a->depth_result = deep(12 * 1024);
}

START_TEST(render_call_runs_deep_and_gives_up_after_a_stop)
{
    CallArg a = {.stuck = false};
    ck_assert(render_call(call_me, &a));
    ck_assert_uint_gt(a.depth_result, 0);
    ck_assert(render_idle());

    static CallArg stuck_arg = {.stuck = true};
    atomic_store(&release, false);
    double start = clock_now();
    ck_assert(!render_call(call_me, &stuck_arg));
    double waited = clock_now() - start;
    ck_assert_msg(waited >= 0.4 && waited < 5, "waited %g s", waited);
    atomic_store(&release, true);
    wait_idle();
    stop_reset();
}
END_TEST

START_TEST(default_threads)
{
    ck_assert_int_ge(render_default_threads(), 1);
    ck_assert_str_eq(render_ray_kind_name(RAY_REFLECTED), "reflected");
}
END_TEST

/* The render loop's tests. */
static Suite *render_suite(void)
{
    Suite *s = suite_create("render");
    TCase *tc = tcase_create("loop");
    tcase_add_test(tc, row_zero_is_the_top);
    tcase_add_test(tc, same_image_whatever_the_thread_count);
    tcase_add_test(tc, nonfinite_pixels_are_magenta_and_counted);
    tcase_add_test(tc, the_largest_float_is_kept);
    tcase_add_test(tc, a_stop_request_ends_the_render);
    tcase_add_test(tc, a_stop_ends_the_wait_whatever_a_pixel_costs);
    tcase_add_test(tc, render_threads_have_a_deep_stack);
    tcase_add_test(tc, render_call_runs_deep_and_gives_up_after_a_stop);
    tcase_add_test(tc, default_threads);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(render_suite)
