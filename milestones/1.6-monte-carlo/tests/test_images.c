/* test_images.c: whole renders: anti-aliased edges, a tiny square light, correlated strata. */
#include <stdio.h>
#include <stdlib.h>

#include "camera.h"
#include "image.h"
#include "testing.h"

/* Renders the scene file at path with the part's program and arguments into img (PFM). */
static void render(const char *path, const char *arguments, Image *img)
{
    char command[2048];
    snprintf(command, sizeof command, "'%s' -q '%s' out.pfm %s", RAYTRA, path, arguments);
    ck_assert_int_eq(system(command), 0);
    Error err;
    ck_assert_msg(image_read_pfm(img, "out.pfm", &err), "%s", err.text);
}

/* The edge of the anti-aliasing test, in pixel coordinates: y = a + b x. */
static const double edge_a = 13.3, edge_b = 0.37;

/* Returns where the camera's ray through image point (x, y) meets the plane z = 0. */
static Vec3 on_plane(const Camera *cam, double x, double y)
{
    Ray r = camera_ray(cam, x, y);
    return ray_at(r, -r.origin.z / r.dir.z);
}

/* Returns the exact fraction of pixel (i, j) below the edge: the integral over the
 * pixel's width of the height of the edge within it (midpoint rule, error ~1e-7). */
static double covered(int i, int j)
{
    int n = 2000;
    double sum = 0;
    for (int k = 0; k < n; k++) {
        double y = edge_a + edge_b * (i + (k + 0.5) / n) - j;
        sum += fmin(1, fmax(0, y));
    }
    return sum / n;
}

/* excerpt: antialiasing-test */
/* A white triangle, lit by an ambient light of 1 only, whose edge crosses the image as
 * y = 13.3 + 0.37 x: a pixel's exact value is the fraction of it the triangle covers.
 * The mean error over the pixels the edge crosses must fall as P grows. */
START_TEST(an_edge_converges_to_the_covered_fraction)
{
    const char *camera = "c 0 0 10   0 0 -1   10   10 10   40 40";
    FILE *f = fopen("edge.scn", "w");
    fprintf(f, "%s\nl a 1 1 1\nm 1 1 1  0 0 0  1  0 0 0\n", camera);
    CameraSpec spec = {.eye = {0, 0, 10}, .view = {0, 0, -1}, .focal = 10, .width = 10,
                       .height = 10, .nx = 40, .ny = 40};
    Camera cam = camera_make(&spec);
    Vec3 a = on_plane(&cam, -200, edge_a - 200 * edge_b);
    Vec3 b = on_plane(&cam, 200, edge_a + 200 * edge_b);
    Vec3 c = on_plane(&cam, 20, -2000);
    /* Counterclockwise as the camera sees it, so that its front faces the camera. */
    if (vec3_cross(vec3_sub(b, a), vec3_sub(c, a)).z < 0) {
        Vec3 keep = b;
        b = c;
        c = keep;
    }
    fprintf(f, "t %.17g %.17g 0  %.17g %.17g 0  %.17g %.17g 0\n", a.x, a.y, b.x, b.y, c.x, c.y);
    fclose(f);
    double previous = INFINITY;
    for (int p = 1; p <= 16; p *= 2) {
        char arguments[32];
        snprintf(arguments, sizeof arguments, "%d", p);
        Image img;
        render("edge.scn", arguments, &img);
        double error = 0;
        int crossed = 0;
        for (int j = 0; j < 40; j++)
            for (int i = 0; i < 40; i++) {
                double want = covered(i, j), got = image_get(&img, i, 39 - j).r;
                if (want == 0 || want == 1)
                    ck_assert_double_eq_tol(got, want, 1e-12); /* all in or all out */
                else
                    error += fabs(got - want), crossed++;
            }
        error /= crossed;
        fprintf(stderr, "P = %2d: mean error %.4f over the %d pixels on the edge\n", p, error,
                crossed);
        ck_assert(error < 0.7 * previous);
        previous = error;
        image_free(&img);
    }
    ck_assert(previous < 0.01);
}
END_TEST
/* end excerpt: antialiasing-test */

/* Writes soft-shadow.scn with its area light line replaced by light. */
static void write_soft_shadow(const char *out, const char *light)
{
    char path[512], line[512];
    snprintf(path, sizeof path, "%s/scenes/soft-shadow.scn", TOP_DIR);
    FILE *in = fopen(path, "r"), *f = fopen(out, "w");
    ck_assert(in != NULL && f != NULL);
    while (fgets(line, sizeof line, in) != NULL)
        fputs(strncmp(line, "l s", 3) == 0 ? light : line, f);
    fclose(in);
    fclose(f);
}

START_TEST(a_tiny_square_light_is_a_point_light)
{
    write_soft_shadow("tiny.scn", "l s 10 60 -10   0 -1 0   1 0 0   0.0001   1 1 1\n");
    write_soft_shadow("point.scn", "l p 10 60 -10   1 1 1\n");
    Image tiny, point;
    render("tiny.scn", "1 3 --scale 0.5", &tiny);
    render("point.scn", "1 3 --scale 0.5", &point);
    int off = 0, n = tiny.width * tiny.height;
    double worst = 0;
    for (int y = 0; y < tiny.height; y++)
        for (int x = 0; x < tiny.width; x++) {
            Color a = image_get(&tiny, x, y), b = image_get(&point, x, y);
            double d = fmax(fabs(a.r - b.r), fmax(fabs(a.g - b.g), fabs(a.b - b.b)));
            if (d > 1e-4)
                off++;
            else
                worst = fmax(worst, d);
        }
    /* Only a pixel whose shadow ray grazes a sphere may tell the two apart. */
    ck_assert_msg(off <= n / 1000, "%d of %d pixels differ", off, n);
    ck_assert(worst < 1e-4);
    image_free(&tiny);
    image_free(&point);
}
END_TEST

/* Returns the mean over pixels of the variance over 12 seeds of soft-shadow.scn at
 * "4 1" (16 rays a pixel, one shadow ray each), sampled as sampling says. */
static double noise(const char *sampling)
{
    char path[512];
    snprintf(path, sizeof path, "%s/scenes/soft-shadow.scn", TOP_DIR);
    enum { SEEDS = 12 };
    Image img[SEEDS];
    for (int s = 0; s < SEEDS; s++) {
        char arguments[128];
        snprintf(arguments, sizeof arguments, "4 1 --scale 0.25 --sampling %s --seed %d",
                 sampling, s);
        render(path, arguments, &img[s]);
    }
    double total = 0;
    for (int y = 0; y < img[0].height; y++)
        for (int x = 0; x < img[0].width; x++) {
            double sum = 0, sum2 = 0;
            for (int s = 0; s < SEEDS; s++) {
                double v = image_get(&img[s], x, y).g;
                sum += v, sum2 += v * v;
            }
            total += (sum2 - sum * sum / SEEDS) / (SEEDS - 1);
        }
    total /= img[0].width * img[0].height;
    for (int s = 0; s < SEEDS; s++)
        image_free(&img[s]);
    return total;
}

START_TEST(correlated_strata_make_less_noise)
{
    double random = noise("random"), jittered = noise("jittered"),
           correlated = noise("correlated");
    fprintf(stderr, "mean pixel variance at 4 1: random %.3g, jittered %.3g, correlated %.3g\n",
            random, jittered, correlated);
    ck_assert(jittered < random);
    ck_assert(correlated < 0.7 * jittered);
}
END_TEST

START_TEST(the_same_seed_gives_the_same_image_and_another_seed_another)
{
    char path[512];
    snprintf(path, sizeof path, "%s/scenes/soft-shadow.scn", TOP_DIR);
    Image a, b, c;
    render(path, "2 2 --scale 0.25 --seed 5 -j 1", &a);
    render(path, "2 2 --scale 0.25 --seed 5 -j 2", &b);
    render(path, "2 2 --scale 0.25 --seed 6 -j 2", &c);
    size_t bytes = sizeof *a.pixels * 3 * (size_t)(a.width * a.height);
    ck_assert_int_eq(memcmp(a.pixels, b.pixels, bytes), 0);
    ck_assert_int_ne(memcmp(a.pixels, c.pixels, bytes), 0);
    image_free(&a);
    image_free(&b);
    image_free(&c);
}
END_TEST

/* The suite of this file. */
static Suite *images_suite(void)
{
    Suite *s = suite_create("images");
    TCase *tc = tcase_create("images");
    tcase_add_test(tc, an_edge_converges_to_the_covered_fraction);
    tcase_add_test(tc, a_tiny_square_light_is_a_point_light);
    tcase_add_test(tc, correlated_strata_make_less_noise);
    tcase_add_test(tc, the_same_seed_gives_the_same_image_and_another_seed_another);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(images_suite)
