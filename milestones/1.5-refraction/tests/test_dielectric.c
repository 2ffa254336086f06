/* test_dielectric.c: Snell's law, the critical angle, Fresnel and Schlick, Beer's law, by hand. */
#include "dielectric.h"
#include "testing.h"

#define PI 3.14159265358979323846

/* The unit direction theta radians from straight down (-y), leaning towards +x. */
static Vec3 down_at(double theta)
{
    return vec3(sin(theta), -cos(theta), 0);
}

START_TEST(snell_hand_picked)
{
    Vec3 up = vec3(0, 1, 0), t;
    /* 30 degrees from air into n = 1.5: sin(theta_t) = 0.5 / 1.5 = 1/3. */
    ck_assert(dielectric_refract(down_at(PI / 6), up, 1 / 1.5, &t));
    ck_assert_vec3_near(t, vec3(1.0 / 3, -sqrt(8.0) / 3, 0), 1e-15);
    /* Head-on: straight through, whatever the indices. */
    ck_assert(dielectric_refract(vec3(0, -1, 0), up, 1 / 2.4, &t));
    ck_assert_vec3_near(t, vec3(0, -1, 0), 1e-16);
    /* Equal indices: no bending at all. */
    ck_assert(dielectric_refract(down_at(1.2), up, 1, &t));
    ck_assert_vec3_near(t, down_at(1.2), 1e-15);
}
END_TEST

START_TEST(snell_at_many_angles)
{
    Vec3 up = vec3(0, 1, 0), t;
    double indices[] = {1.33, 1.5, 2.4, 0.8};
    for (int k = 0; k < 4; k++)
        for (double deg = 0; deg < 90; deg += 7.5) {
            double n = indices[k], theta = deg * PI / 180;
            Vec3 d = down_at(theta);
            bool refracts = dielectric_refract(d, up, 1 / n, &t);
            /* From air into n > 1 there is always a refracted ray. */
            ck_assert(refracts || n < 1);
            if (!refracts)
                continue;
            /* Unit length, on the far side, in the plane of incidence... */
            ck_assert_double_eq_tol(vec3_length(t), 1, 1e-15);
            ck_assert(t.y < 0);
            ck_assert_double_eq_tol(t.z, 0, 1e-16);
            /* ... and Snell: 1 sin(theta) = n sin(theta_t); sin(theta_t) is t's x. */
            ck_assert_double_eq_tol(sin(theta), n * t.x, 1e-15);
            /* Going back the other way retraces the ray: light paths are reversible. */
            Vec3 back;
            ck_assert(dielectric_refract(vec3_neg(t), vec3_neg(up), n, &back));
            ck_assert_vec3_near(back, vec3_neg(d), 1e-14);
        }
}
END_TEST

START_TEST(critical_angle)
{
    /* From inside n = 1.5 towards air: sin(theta_c) = 1 / 1.5, theta_c = 41.81 degrees. */
    Vec3 up = vec3(0, 1, 0), t = vec3(7, 7, 7);
    double critical = asin(1 / 1.5);
    ck_assert_double_eq_tol(critical * 180 / PI, 41.8103148958, 1e-9);
    Vec3 below = vec3(sin(critical - 1e-6), cos(critical - 1e-6), 0);
    Vec3 above = vec3(sin(critical + 1e-6), cos(critical + 1e-6), 0);
    /* Just below: a refracted ray, leaving almost along the surface. */
    ck_assert(dielectric_refract(below, vec3_neg(up), 1.5, &t));
    ck_assert(t.y > 0 && t.y < 2e-3 && t.x > 0.999998);
    /* Just above: none; the direction is left untouched. */
    Vec3 untouched = vec3(7, 7, 7);
    ck_assert(!dielectric_refract(above, vec3_neg(up), 1.5, &untouched));
    ck_assert_vec3_near(untouched, vec3(7, 7, 7), 0);
    /* Into the denser side there is never total internal reflection, even at grazing. */
    ck_assert(dielectric_refract(vec3(1, -1e-9, 0), up, 1 / 1.5, &t));
    ck_assert_double_eq_tol(t.x, 1 / 1.5, 1e-12);
}
END_TEST

START_TEST(reflectance_head_on_is_r0)
{
    double indices[] = {1, 1.33, 1.5, 2.4};
    /* Hand-worked R0 = ((n - 1) / (n + 1))^2: 0, 0.02006..., 0.04, 0.16955... */
    double r0[] = {0, 0.33 * 0.33 / (2.33 * 2.33), 0.04, 1.4 * 1.4 / (3.4 * 3.4)};
    for (int k = 0; k < 4; k++) {
        ck_assert_double_eq_tol(dielectric_reflectance(FRESNEL_SCHLICK, indices[k], 1), r0[k],
                                1e-16);
        ck_assert_double_eq_tol(dielectric_reflectance(FRESNEL_EXACT, indices[k], 1), r0[k],
                                1e-16);
    }
}
END_TEST

START_TEST(reflectance_grows_to_one_at_grazing)
{
    double indices[] = {1.33, 1.5, 2.4};
    FresnelModel models[] = {FRESNEL_SCHLICK, FRESNEL_EXACT};
    for (int m = 0; m < 2; m++)
        for (int k = 0; k < 3; k++) {
            double previous = 0;
            for (double cos = 1; cos >= 0; cos -= 1.0 / 64) {
                double r = dielectric_reflectance(models[m], indices[k], cos);
                ck_assert(r >= previous - 1e-15 && r <= 1);
                previous = r;
            }
            ck_assert_double_eq_tol(dielectric_reflectance(models[m], indices[k], 0), 1, 1e-15);
            ck_assert_double_eq_tol(dielectric_reflectance(models[m], indices[k], 1e-9), 1, 1e-7);
        }
}
END_TEST

START_TEST(exact_reflected_plus_transmitted_is_one)
{
    /* R from the reflected amplitudes and T from the transmitted ones are computed apart;
     * with no absorption at the surface they must add up to 1, both ways through it. */
    double indices[] = {1.01, 1.33, 1.5, 2.4, 0.7};
    for (int k = 0; k < 5; k++)
        for (double cos_i = 1; cos_i > 0.01; cos_i -= 0.03) {
            double pairs[2][2] = {{1, indices[k]}, {indices[k], 1}};
            for (int way = 0; way < 2; way++) {
                double n_i = pairs[way][0], n_t = pairs[way][1];
                double sin2_t = n_i * n_i / (n_t * n_t) * (1 - cos_i * cos_i);
                if (sin2_t > 1)
                    continue; /* total internal reflection */
                double cos_t = sqrt(1 - sin2_t);
                double r = dielectric_fresnel_exact(n_i, n_t, cos_i, cos_t);
                double t = dielectric_transmittance_exact(n_i, n_t, cos_i, cos_t);
                ck_assert_double_eq_tol(r + t, 1, 1e-14);
                /* And R is the same from the other side, at the other angle. */
                ck_assert_double_eq_tol(r, dielectric_fresnel_exact(n_t, n_i, cos_t, cos_i),
                                        1e-15);
            }
        }
}
END_TEST

START_TEST(index_one_reflects_nothing_only_when_exact)
{
    for (double cos = 1; cos > 0; cos -= 0.05) {
        /* Air to air: no surface at all for the Fresnel equations (but for rounding). */
        ck_assert_double_eq_tol(dielectric_reflectance(FRESNEL_EXACT, 1, cos), 0, 1e-25);
        /* Schlick keeps (1 - cos)^5 with R0 = 0: a rim of reflection at grazing angles. */
        ck_assert_double_eq_tol(dielectric_reflectance(FRESNEL_SCHLICK, 1, cos), pow(1 - cos, 5),
                                1e-15);
    }
    ck_assert(dielectric_reflectance(FRESNEL_SCHLICK, 1, 0.1) > 0.59);
    /* Exactly grazing, where the exact equations are 0 / 0: all reflected, never NaN. */
    ck_assert_double_eq(dielectric_reflectance(FRESNEL_EXACT, 1, 0), 1);
    ck_assert_double_eq(dielectric_reflectance(FRESNEL_EXACT, 0.5, 0), 1);
    ck_assert_double_eq(dielectric_reflectance(FRESNEL_EXACT, 0.5, sqrt(0.75)), 1);
}
END_TEST

START_TEST(schlick_against_exact)
{
    /* At n = 1.5 Schlick is within 0.02 of the exact R up to 75 degrees from the normal
     * (it is low by 0.019 at 60), and within 0.036 at every angle, the worst near 85
     * degrees, where it is high: close enough for the textbook's choice. */
    double worst = 0, worst_cos = 1;
    for (double cos = 1; cos >= 0; cos -= 1.0 / 1024) {
        double error = fabs(dielectric_reflectance(FRESNEL_SCHLICK, 1.5, cos) -
                            dielectric_reflectance(FRESNEL_EXACT, 1.5, cos));
        if (cos > 0.259)
            ck_assert(error < 0.02);
        if (error > worst)
            worst = error, worst_cos = cos;
    }
    ck_assert(worst > 0.03 && worst < 0.036);
    ck_assert(acos(worst_cos) * 180 / PI > 83 && acos(worst_cos) * 180 / PI < 87);
}
END_TEST

START_TEST(beer_law)
{
    Color a = color(0.5, 0.9, 1);
    ck_assert_color_near(dielectric_beer(a, 0), color(1, 1, 1), 0);
    ck_assert_color_near(dielectric_beer(a, 1), a, 1e-16);
    ck_assert_color_near(dielectric_beer(a, 3), color(0.125, 0.729, 1), 1e-15);
    /* e^(ln(a) s), the slides' form: the same numbers, and never above 1. */
    for (double s = 0; s < 50; s += 2.5) {
        Color c = dielectric_beer(a, s);
        ck_assert_double_eq_tol(c.r, exp(log(0.5) * s), 1e-15);
        ck_assert(c.r <= 1 && c.g <= 1 && c.b == 1);
        /* Two stretches one after the other absorb as one: a^s1 a^s2 = a^(s1 + s2). */
        ck_assert_color_near(color_mul(dielectric_beer(a, s), dielectric_beer(a, 1.75)),
                             dielectric_beer(a, s + 1.75), 1e-15);
    }
    /* The textbook's sign, e^(-ln(a) s), would make light grow: 2^3 = 8 for a = 0.5. */
    ck_assert_double_eq_tol(exp(-log(0.5) * 3), 8, 1e-14);
}
END_TEST

START_TEST(fresnel_names)
{
    FresnelModel m = FRESNEL_EXACT;
    ck_assert(dielectric_fresnel_from_name("schlick", &m) && m == FRESNEL_SCHLICK);
    ck_assert(dielectric_fresnel_from_name("exact", &m) && m == FRESNEL_EXACT);
    ck_assert(!dielectric_fresnel_from_name("Exact", &m));
    ck_assert(!dielectric_fresnel_from_name("", &m));
}
END_TEST

/* The optics' tests. */
static Suite *dielectric_suite(void)
{
    Suite *s = suite_create("dielectric");
    TCase *tc = tcase_create("optics");
    tcase_add_test(tc, snell_hand_picked);
    tcase_add_test(tc, snell_at_many_angles);
    tcase_add_test(tc, critical_angle);
    tcase_add_test(tc, reflectance_head_on_is_r0);
    tcase_add_test(tc, reflectance_grows_to_one_at_grazing);
    tcase_add_test(tc, exact_reflected_plus_transmitted_is_one);
    tcase_add_test(tc, index_one_reflects_nothing_only_when_exact);
    tcase_add_test(tc, schlick_against_exact);
    tcase_add_test(tc, beer_law);
    tcase_add_test(tc, fresnel_names);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(dielectric_suite)
