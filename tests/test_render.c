/* test_render.c: the render loop: pixels, thread counts, counts, NaN and overflow, stop. */
#include <float.h>
#include <signal.h>
#include <string.h>

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
    ck_assert_int_eq(stop_signal(), SIGINT);
    /* With one thread, the rows after the stop were never rendered. */
    ck_assert_color_near(image_get(&img, 0, 99), color(0, 0, 0), 0);
    stop_reset();
    ck_assert(!stop_requested());
    image_free(&img);
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
    tcase_add_test(tc, default_threads);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(render_suite)
