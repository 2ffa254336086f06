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

/* Returns the square light of these tests. */
static Light square(void)
{
    Light l = {.kind = LIGHT_AREA, .position = {0, H, 0}, .direction = {0, -1, 0},
               .u = {1, 0, 0}, .size = SIDE, .color = {1, 1, 1}};
    l.v = vec3_cross(l.u, l.direction);
    return l;
}

/* Says, for messages, how sampling places the shadow rays on the light. */
static const char *placed(Sampling sampling)
{
    return sampling == SAMPLING_RANDOM     ? "placed at random"
           : sampling == SAMPLING_JITTERED ? "jittered, one in each sub-square"
                                           : "in correlated strata";
}

/* Checks that area_point of the test's square at (ru, rv) is want, what, to within tol. */
static void check_area_point(double ru, double rv, Vec3 want, const char *what, double tol)
{
    Light l = square();
    Vec3 got = area_point(&l, ru, rv);
    ck_assert_msg(fabs(got.x - want.x) <= tol && fabs(got.y - want.y) <= tol &&
                      fabs(got.z - want.z) <= tol,
                  "area_point(light, %g, %g) is (%.17g, %.17g, %.17g), not %s (%g, %g, %g): the "
                  "square's centre plus (ru - 1/2) sides along u and (rv - 1/2) sides along v = "
                  "u x n (the square is 8 wide at (0, 10, 0), u = (1, 0, 0), v = (0, 0, -1))",
                  ru, rv, got.x, got.y, got.z, what, want.x, want.y, want.z);
}

START_TEST(light_points_span_the_square)
{
    check_area_point(0.5, 0.5, vec3(0, H, 0), "its centre", 0);
    check_area_point(0, 0, vec3(-4, H, 4), "the corner at -u and -v", 1e-15); /* v = -z */
    check_area_point(1, 1, vec3(4, H, -4), "the corner at +u and +v", 1e-15);
    check_area_point(1, 0, vec3(4, H, 4), "the corner at +u and -v", 1e-15);
}
END_TEST

/* Tells whether colours a and b agree to within tol in every component (never if NaN). */
static bool color_near(Color a, Color b, double tol)
{
    return fabs(a.r - b.r) <= tol && fabs(a.g - b.g) <= tol && fabs(a.b - b.b) <= tol;
}

START_TEST(each_of_n_samples_carries_one_nth_and_only_in_front)
{
    Light l = square();
    Incident in = area_incident(&l, l.position, vec3(0, 0, 0), 4, false);
    ck_assert_msg(color_near(in.radiance, color(0.25, 0.25, 0.25), 0),
                  "area_incident, from the centre of a white square light shared by count = 4 "
                  "shadow rays, sends (%g, %g, %g) to a point 10 below it, not 1/4 of the "
                  "light's colour, (0.25, 0.25, 0.25): each of N samples is a point light of 1/N "
                  "of the colour",
                  in.radiance.r, in.radiance.g, in.radiance.b);
    ck_assert_msg(in.dir.x == 0 && in.dir.y == 1 && in.dir.z == 0,
                  "area_incident gives (%g, %g, %g) as the direction towards the light from a "
                  "point right under the sample, not (0, 1, 0): the unit vector from the point "
                  "towards the sample, as light_incident gives it for a point light there",
                  in.dir.x, in.dir.y, in.dir.z);
    in = area_incident(&l, l.position, vec3(0, 0, 0), 4, true);
    ck_assert_msg(color_near(in.radiance, color(0.0025, 0.0025, 0.0025), 1e-18),
                  "area_incident with falls_off sends (%g, %g, %g) from 10 away, not "
                  "(1/4) / 10^2 = 0.0025: a point light of 1/N of the colour, falling off as 1/r^2",
                  in.radiance.r, in.radiance.g, in.radiance.b);
    /* Behind the square, and in its plane, it sends nothing. */
    in = area_incident(&l, l.position, vec3(0, 20, 0), 1, false);
    ck_assert_msg(color_is_black(in.radiance),
                  "area_incident sends (%g, %g, %g) to a point 10 above the square, which faces "
                  "down: the square shines only on the side its normal n faces, so a point "
                  "behind it receives nothing",
                  in.radiance.r, in.radiance.g, in.radiance.b);
    in = area_incident(&l, l.position, vec3(30, H, 0), 1, false);
    ck_assert_msg(color_is_black(in.radiance),
                  "area_incident sends (%g, %g, %g) to a point in the square's own plane: only "
                  "a point strictly on the side its normal n faces receives light",
                  in.radiance.r, in.radiance.g, in.radiance.b);
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
    ck_assert_msg(montecarlo_init(&s->mc, &s->scene, surfaces_brute_force(&s->scene), &opts),
                  "montecarlo_init refuses the default options (P = S = 1)");
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
    ck_assert_msg(stats.rays[RAY_SHADOW] == (unsigned long long)(side * side),
                  "with S = %d, the square light is sampled by %llu shadow rays, not S x S = %d",
                  side, stats.rays[RAY_SHADOW], side * side);
    /* Said here, before a mean or an RMSE is taken of it. */
    ck_assert_msg(isfinite(c.r),
                  "an estimate of the light that reaches the floor point (0, 0, 1) from the "
                  "square light, by S x S shadow rays (S = %d) %s, is %g, not a finite number: "
                  "does area_incident divide by a count of 0, or do area_point and "
                  "montecarlo_light_point (strata_point) give a point that is not a number?",
                  side, placed(sampling), c.r);
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
    char gap[80] = "though all the estimates are the same";
    if (se > 0)
        snprintf(gap, sizeof gap, "%.1f standard errors (%.3g) away, more than 3",
                 fabs(mean - want) / se, se);
    ck_assert_msg(fabs(mean - want) < 3 * se,
                  "the mean of %d estimates of the light that reaches the floor point (0, 0, 1) "
                  "from the square light, %s, by S x S shadow rays (S = %d) %s, is %.9g, but the "
                  "exact integral is %.9g, %s: each shadow ray must be a point light of 1/S^2 of "
                  "the light's colour (area_incident), at a point uniform over the whole square "
                  "(area_point, at the (ru, rv) of montecarlo_light_point)",
                  m, occluded ? "partly hidden by an occluder's edge" : "all of it in view", side,
                  placed(sampling), mean, want, gap);
    /* The test can tell a wrong value. */
    ck_assert_msg(se < 0.02 * want,
                  "the mean of %d estimates (S x S shadow rays, S = %d, %s) has a standard error "
                  "of %.3g, %.1f%% of the exact value: too noisy for the test to tell a wrong "
                  "mean (it needs under 2%%); does each shadow ray carry more than 1/S^2 of the "
                  "light (area_incident)?",
                  m, side, placed(sampling), se, 100 * se / want);
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

/* Checks that slope, how the RMSE of an estimate falls with N = S^2 shadow rays placed by
 * sampling (random: as N^-1/2 within lo and hi; jittered: faster than N^hi) with the
 * light all in view or behind an occluder's edge, lies between lo and hi. */
static void check_slope(double slope, double lo, double hi, bool occluded, Sampling sampling)
{
    const char *view = occluded ? "an occluder's edge across the light" : "all the light in view";
    ck_assert_msg(isfinite(slope),
                  "with %s and shadow rays %s, the RMSE of an estimate against N = S^2 shadow "
                  "rays fits no power of N (slope %g): is it 0, or infinite, for some S?",
                  view, placed(sampling), slope);
    if (sampling == SAMPLING_RANDOM)
        ck_assert_msg(slope > lo && slope < hi,
                      "with %s and shadow rays placed at random, the RMSE of an estimate falls "
                      "as N^%.2f with N = S^2 shadow rays; a mean of N independent samples "
                      "falls as N^-0.5 (the test allows N^%g to N^%g): steeper, and "
                      "strata_point's random mode stratifies (it must ignore k); flatter, and the "
                      "S x S points are not independent uniform points of the light, or not each "
                      "1/N of it (area_incident's count)",
                      view, slope, lo, hi);
    else
        ck_assert_msg(slope < hi,
                      "with %s and jittered shadow rays, the RMSE of an estimate falls only as "
                      "N^%.2f with N = S^2 shadow rays; one in each of S x S sub-squares of the "
                      "light makes it fall about as N^%s (the test asks for faster than N^%g): "
                      "strata_point's jittered mode must put sample q uniformly in sub-square q "
                      "(column q %% S, row q / S), and montecarlo_light_point must ask it for q "
                      "of S",
                      view, slope, occluded ? "-0.75 across an edge" : "-1 for a smooth light", hi);
}

START_TEST(stratified_error_falls_faster_than_random)
{
    double random_smooth = error_slope(false, SAMPLING_RANDOM);
    double jittered_smooth = error_slope(false, SAMPLING_JITTERED);
    double random_edge = error_slope(true, SAMPLING_RANDOM);
    double jittered_edge = error_slope(true, SAMPLING_JITTERED);
    fprintf(stderr, "RMSE ~ N^slope: random %.2f, jittered %.2f; with an occluder's edge: "
                    "random %.2f, jittered %.2f\n",
            random_smooth, jittered_smooth, random_edge, jittered_edge);
    check_slope(random_smooth, -0.6, -0.4, false, SAMPLING_RANDOM);
    check_slope(random_edge, -0.6, -0.4, true, SAMPLING_RANDOM);
    /* Theory for a 2-D integral: N^-1 for a smooth integrand, N^-3/4 across an edge. */
    check_slope(jittered_smooth, -INFINITY, -0.8, false, SAMPLING_JITTERED);
    check_slope(jittered_edge, -INFINITY, -0.62, true, SAMPLING_JITTERED);
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
