/* test_images.c: whole renders: anti-aliased edges, a tiny square light, correlated strata. */
#include <stdio.h>
#include <stdlib.h>

#include "camera.h"
#include "image.h"
#include "testing.h"

/* Renders the scene file at path with the part's program and arguments into img (PFM);
 * fails, in words, when raytra fails or says that a pixel came out NaN or infinite (it
 * writes such a pixel magenta, which no statistic would see for what it is). */
static void render(const char *path, const char *arguments, Image *img)
{
    char command[2048], said[2048] = "";
    snprintf(command, sizeof command, "'%s' -q '%s' out.pfm %s 2>render.log", RAYTRA, path,
             arguments);
    int status = system(command);
    FILE *log = fopen("render.log", "r");
    if (log != NULL) {
        said[fread(said, 1, sizeof said - 1, log)] = '\0';
        fclose(log);
    }
    ck_assert_msg(status == 0, "raytra fails (wait status %d) to render %s with %s:\n%s", status,
                  path, arguments, said);
    const char *nonfinite = strstr(said, "came out NaN or infinite"), *first;
    int x = 0, y = 0;
    if (nonfinite != NULL && (first = strstr(nonfinite, "the first is at column ")) != NULL)
        sscanf(first, "the first is at column %d, row %d", &x, &y);
    ck_assert_msg(nonfinite == NULL,
                  "rendering %s with %s, raytra says that pixels %.*s: a pixel is the mean of its "
                  "P x P rays (montecarlo_pixel, 1/P^2 each), each lit by S x S shadow rays of "
                  "1/S^2 of the light (area_incident); does something divide by 0? "
                  "--trace-pixel %d,%d shows the first one's rays",
                  path, arguments, (int)strcspn(nonfinite ? nonfinite : "", ".\n"),
                  nonfinite ? nonfinite : "", x, y);
    Error err;
    ck_assert_msg(image_read_pfm(img, "out.pfm", &err), "cannot read the render of %s: %s", path,
                  err.text);
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
                if (want == 0 || want == 1) /* all in or all out */
                    ck_assert_msg(fabs(got - want) < 1e-12,
                                  "pixel %d,%d lies all %s the triangle, yet at P = %d it is "
                                  "%.17g, not %g: every ray of a pixel goes through a point of "
                                  "the pixel (montecarlo_point), and the pixel is their mean "
                                  "(montecarlo_pixel)",
                                  i, 39 - j, want == 1 ? "inside" : "outside", p, got, want);
                else
                    error += fabs(got - want), crossed++;
            }
        error /= crossed;
        fprintf(stderr, "P = %2d: mean error %.4f over the %d pixels on the edge\n", p, error,
                crossed);
        ck_assert_msg(error < 0.7 * previous,
                      "at P = %d the mean error of the %d pixels on the edge is %.4f, not below "
                      "0.7 of P = %d's %.4f: more rays a pixel must measure the fraction it "
                      "covers better, montecarlo_point putting ray k at a random point of "
                      "sub-square k, and montecarlo_pixel averaging them",
                      p, crossed, error, p / 2, previous);
        previous = error;
        image_free(&img);
    }
    ck_assert_msg(previous < 0.01,
                  "at P = 16 the mean error of the pixels on the edge is %.4f, not under 0.01: "
                  "256 jittered rays a pixel measure the fraction it covers to about 0.005",
                  previous);
}
END_TEST
/* end excerpt: antialiasing-test */

/* Writes soft-shadow.scn with its area light line replaced by light. */
static void write_soft_shadow(const char *out, const char *light)
{
    char path[512], line[512];
    snprintf(path, sizeof path, "%s/scenes/soft-shadow.scn", TOP_DIR);
    FILE *in = fopen(path, "r"), *f = fopen(out, "w");
    ck_assert_msg(in != NULL && f != NULL, "cannot read %s, or cannot write %s", path, out);
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
    ck_assert_msg(off <= n / 1000,
                  "%d of the %d pixels of soft-shadow.scn (1 3 --scale 0.5) lit by a square light "
                  "0.0001 wide differ by more than 1e-4 from the scene lit by a point light at its "
                  "centre, more than 1 in 1000: a tiny square light lights as a point light, each "
                  "of its S x S shadow rays a point light of 1/S^2 of its colour (area_incident) "
                  "at a point of the square (area_point)",
                  off, n);
    ck_assert_msg(worst < 1e-4,
                  "the pixels of soft-shadow.scn lit by a tiny square light that agree with the "
                  "point light's agree only to %g, not under 1e-4",
                  worst);
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
    ck_assert_msg(jittered < random,
                  "at 4 1 (16 rays a pixel, one shadow ray each), the mean variance of a pixel of "
                  "soft-shadow.scn over 12 seeds is %.3g with --sampling jittered, not below "
                  "random's %.3g: one ray in each of the pixel's 4 x 4 sub-squares "
                  "(montecarlo_point, strata_point's jittered mode) must make less noise than "
                  "rays anywhere in it",
                  jittered, random);
    ck_assert_msg(correlated < 0.7 * jittered,
                  "at 4 1, correlated strata give soft-shadow.scn a mean pixel variance of %.3g, "
                  "not below 0.7 of jittered's %.3g: with S = 1, montecarlo_light_point must put "
                  "a sample's shadow ray, jittered, in the light stratum the sample carries "
                  "(sample->stratum of sample->strata_side x sample->strata_side), so that the "
                  "pixel's 16 shadow rays cover the light once each",
                  correlated, jittered);
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
    ck_assert_msg(memcmp(a.pixels, b.pixels, bytes) == 0,
                  "soft-shadow.scn at 2 2 --seed 5 renders otherwise on 1 and on 2 threads: a "
                  "pixel's random numbers must come from (seed, pixel, sample) alone, so "
                  "montecarlo_point and montecarlo_light_point draw them from the Rng they are "
                  "given, never from a generator of their own");
    ck_assert_msg(memcmp(a.pixels, c.pixels, bytes) != 0,
                  "soft-shadow.scn at 2 2 renders the same with --seed 5 and --seed 6: the "
                  "points of the rays and of the shadow rays must be drawn from the Rng they are "
                  "given (montecarlo_point, montecarlo_light_point, strata_point)");
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
