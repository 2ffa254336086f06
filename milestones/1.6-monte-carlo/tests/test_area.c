/* test_area.c: points on a square light, and the light it sends, against numerical quadrature. */
#include "area.h"
#include "direct.h"
#include "montecarlo.h"
#include "secondary.h"
#include "surfaces.h"
#include "testing.h"

/* The square light of these tests: 8 wide, 10 above the floor y = 0, facing down. */
enum { H = 10, SIDE = 8 };
static const double occluder_height = 5, occluder_edge = -0.37;

static Light square(void)
{
    Light l = {.kind = LIGHT_AREA, .position = {0, H, 0}, .direction = {0, -1, 0},
               .u = {1, 0, 0}, .size = SIDE, .color = {1, 1, 1}};
    l.v = vec3_cross(l.u, l.direction);
    return l;
}

START_TEST(light_points_span_the_square)
{
    Light l = square();
    ck_assert_vec3_near(area_point(&l, 0.5, 0.5), l.position, 0);
    ck_assert_vec3_near(area_point(&l, 0, 0), vec3(-4, H, 4), 1e-15); /* v = u x n = -z */
    ck_assert_vec3_near(area_point(&l, 1, 1), vec3(4, H, -4), 1e-15);
    ck_assert_vec3_near(area_point(&l, 1, 0), vec3(4, H, 4), 1e-15);
}
END_TEST

START_TEST(each_of_n_samples_carries_one_nth_and_only_in_front)
{
    Light l = square();
    Incident in = area_incident(&l, l.position, vec3(0, 0, 0), 4, false);
    ck_assert_color_near(in.radiance, color(0.25, 0.25, 0.25), 0);
    ck_assert_vec3_near(in.dir, vec3(0, 1, 0), 0);
    in = area_incident(&l, l.position, vec3(0, 0, 0), 4, true);
    ck_assert_color_near(in.radiance, color(0.0025, 0.0025, 0.0025), 1e-18);
    /* Behind the square, and in its plane, it sends nothing. */
    in = area_incident(&l, l.position, vec3(0, 20, 0), 1, false);
    ck_assert(color_is_black(in.radiance));
    in = area_incident(&l, l.position, vec3(30, H, 0), 1, false);
    ck_assert(color_is_black(in.radiance));
}
END_TEST

/* A floor point's estimator: a scene of the square light (falling off as 1/r^2) and,
 * when occluded, a large triangle at height 5 covering x < -0.37 (its edge along z, on no
 * stratum boundary). */
typedef struct {
    Scene scene;
    Light light;
    Vec3 corners[3];
    Face occluder;
    Material white;
    MonteCarlo mc;
} Setup;

static void setup_make(Setup *s, bool occluded)
{
    s->light = square();
    s->white = (Material){.diffuse = {1, 1, 1}, .phong = 1};
    double h = occluder_height, e = occluder_edge;
    s->corners[0] = vec3(e, h, -1000);
    s->corners[1] = vec3(e, h, 1000);
    s->corners[2] = vec3(-1000, h, 0);
    s->occluder = (Face){.corner = {0, 1, 2}};
    s->scene = (Scene){.convention = CONVENTION_FALL2016, .materials = &s->white,
                       .material_count = 1, .lights = &s->light, .light_count = 1,
                       .vertices = s->corners, .vertex_count = 3,
                       .triangles = &s->occluder, .triangle_count = occluded ? 1 : 0};
    Options opts; /* P = S = 1, --max-depth 20, the default ray offset */
    cli_defaults(&opts, montecarlo_part_options);
    ck_assert(montecarlo_init(&s->mc, &s->scene, surfaces_brute_force(&s->scene), &opts));
}

/* One estimate of the light reaching floor point p = (0, 0, 1), with S x S shadow rays
 * placed by sampling, from random numbers of stream trial. */
static double estimate(Setup *s, Sampling sampling, int side, uint64_t trial)
{
    s->mc.sampling = sampling;
    s->mc.light_side = side;
    Rng rng = rng_make(rng_hash(trial), (uint64_t)side);
    Sample sample = {.mc = &s->mc, .rng = &rng};
    Tracer tr = tracer_extend(&s->mc.tracer, &montecarlo_hooks, &sample);
    RayStats stats = {{0}};
    Path path = {.stats = &stats};
    Hit hit = {.t = 10, .point = {0, 0, 1}, .normal = {0, 1, 0}, .kind = SURFACE_TRIANGLE};
    Ray down = {{0, 10, 1}, {0, -1, 0}};
    Color c = direct_radiance(&tr, &hit, down, 0, &path);
    ck_assert_uint_eq(stats.rays[RAY_SHADOW], (unsigned long long)(side * side));
    return c.r;
}

/* The integrand at light point (x, z): cos(theta)/r^2 = H / r^3, over the light's area. */
static double integrand(double x, double z)
{
    double r2 = x * x + (double)H * H + (z - 1) * (z - 1);
    return H / (r2 * sqrt(r2)) / (SIDE * SIDE);
}

/* excerpt: irradiance-quadrature */
/* Returns the exact mean of the estimator: the integral of cos(theta)/r^2 over the part
 * of the light that p = (0, 0, 1) sees, by composite Simpson's rule on a 512 x 512 grid.
 * The occluder hides the light points whose segment to p crosses y = 5 at x < -0.37,
 * which are those with x < -0.37 * H / 5: the visible part is a rectangle. */
static double exact(bool occluded)
{
    double x0 = occluded ? occluder_edge * H / occluder_height : -SIDE / 2.0;
    double x1 = SIDE / 2.0, z0 = -SIDE / 2.0, z1 = SIDE / 2.0;
    int n = 512;
    double hx = (x1 - x0) / n, hz = (z1 - z0) / n, sum = 0;
    for (int a = 0; a <= n; a++)
        for (int b = 0; b <= n; b++) {
            double wa = a == 0 || a == n ? 1 : a % 2 ? 4 : 2;
            double wb = b == 0 || b == n ? 1 : b % 2 ? 4 : 2;
            sum += wa * wb * integrand(x0 + a * hx, z0 + b * hz);
        }
    return sum * hx * hz / 9;
}
/* end excerpt: irradiance-quadrature */

/* Checks that the mean of m estimates is within 3 standard errors of the exact value. */
static void check_mean(bool occluded, Sampling sampling, int side, int m)
{
    Setup s;
    setup_make(&s, occluded);
    double sum = 0, sum2 = 0;
    for (int k = 0; k < m; k++) {
        double e = estimate(&s, sampling, side, (uint64_t)k);
        sum += e;
        sum2 += e * e;
    }
    double mean = sum / m, var = (sum2 - m * mean * mean) / (m - 1), se = sqrt(var / m);
    double want = exact(occluded);
    ck_assert_msg(fabs(mean - want) < 3 * se,
                  "occluded %d sampling %d S %d: mean %.9g, exact %.9g, standard error %.3g",
                  occluded, sampling, side, mean, want, se);
    ck_assert(se < 0.02 * want); /* the test can tell a wrong value */
}

START_TEST(estimates_average_to_the_exact_irradiance)
{
    check_mean(false, SAMPLING_RANDOM, 1, 20000);
    check_mean(false, SAMPLING_JITTERED, 4, 2000);
    check_mean(true, SAMPLING_RANDOM, 1, 20000);
    check_mean(true, SAMPLING_JITTERED, 4, 2000);
    check_mean(true, SAMPLING_RANDOM, 3, 4000);
}
END_TEST

/* excerpt: error-slope */
/* Returns the slope of log(RMSE) against log(N), N = S^2 shadow rays, for S = 1, 2, 4,
 * 8, 16, each RMSE over 300 estimates: about -1/2 for independent points (the error
 * of a mean of N), steeper for strata, whose points cannot clump. */
static double error_slope(bool occluded, Sampling sampling)
{
    Setup s;
    setup_make(&s, occluded);
    double want = exact(occluded), sx = 0, sy = 0, sxx = 0, sxy = 0;
    int points = 0;
    for (int side = 1; side <= 16; side *= 2, points++) {
        double sum2 = 0;
        for (int k = 0; k < 300; k++) {
            double d = estimate(&s, sampling, side, 1000000 + (uint64_t)k) - want;
            sum2 += d * d;
        }
        double x = log((double)side * side), y = log(sqrt(sum2 / 300));
        sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    return (points * sxy - sx * sy) / (points * sxx - sx * sx); /* least squares */
}
/* end excerpt: error-slope */

START_TEST(stratified_error_falls_faster_than_random)
{
    double random_smooth = error_slope(false, SAMPLING_RANDOM);
    double jittered_smooth = error_slope(false, SAMPLING_JITTERED);
    double random_edge = error_slope(true, SAMPLING_RANDOM);
    double jittered_edge = error_slope(true, SAMPLING_JITTERED);
    fprintf(stderr, "RMSE ~ N^slope: random %.2f, jittered %.2f; with an occluder's edge: "
                    "random %.2f, jittered %.2f\n",
            random_smooth, jittered_smooth, random_edge, jittered_edge);
    ck_assert(random_smooth > -0.6 && random_smooth < -0.4);
    ck_assert(random_edge > -0.6 && random_edge < -0.4);
    /* Theory for a 2-D integral: N^-1 for a smooth integrand, N^-3/4 across an edge. */
    ck_assert(jittered_smooth < -0.8);
    ck_assert(jittered_edge < -0.62);
}
END_TEST

/* The suite of this file. */
static Suite *area_suite(void)
{
    Suite *s = suite_create("area");
    TCase *tc = tcase_create("area");
    tcase_add_test(tc, light_points_span_the_square);
    tcase_add_test(tc, each_of_n_samples_carries_one_nth_and_only_in_front);
    tcase_add_test(tc, estimates_average_to_the_exact_irradiance);
    tcase_add_test(tc, stratified_error_falls_faster_than_random);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(area_suite)
