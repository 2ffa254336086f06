/* test_shade.c: Blinn-Phong and the lights, against values worked out by hand. */
#include "shade.h"
#include "testing.h"

static const Material red_glossy = {
    .diffuse = {0.6, 0.2, 0.1}, .specular = {0.3, 0.3, 0.3}, .phong = 10};

/* What a light of colour I sends along unit direction l (towards the light). */
static Incident from(Vec3 l, Color I)
{
    return (Incident){.dir = vec3_normalize(l), .distance = 1, .radiance = I};
}

START_TEST(light_straight_above_gives_kd_I)
{
    /* n.l = 1; seen from the side the highlight is far away, and with ks = 0 it is gone. */
    Material matte = {.diffuse = {0.6, 0.2, 0.1}, .phong = 10};
    Incident in = from(vec3(0, 1, 0), color(2, 1, 0.5));
    Color c = shade_blinn_phong(&matte, vec3(0, 1, 0), vec3_normalize(vec3(1, 1, 0)), &in);
    ck_assert_color_near(c, color(1.2, 0.2, 0.05), 1e-15);
}
END_TEST

START_TEST(specular_peak_at_the_mirror_direction)
{
    /* Light and eye both straight above: h = n, so kd I + ks I. */
    Incident in = from(vec3(0, 1, 0), color(2, 1, 0.5));
    Color c = shade_blinn_phong(&red_glossy, vec3(0, 1, 0), vec3(0, 1, 0), &in);
    ck_assert_color_near(c, color(2 * 0.9, 0.5, 0.5 * 0.4), 1e-15);
    /* Light 60 degrees from the normal, eye at its mirror image: h = n again, and the
     * diffuse part is halved by cos 60 = 1/2: I (kd / 2 + ks). */
    Incident slant = from(vec3(-sin(M_PI / 3), cos(M_PI / 3), 0), color(1, 1, 1));
    Vec3 mirror = vec3(sin(M_PI / 3), cos(M_PI / 3), 0);
    c = shade_blinn_phong(&red_glossy, vec3(0, 1, 0), mirror, &slant);
    ck_assert_color_near(c, color(0.3 + 0.3, 0.1 + 0.3, 0.05 + 0.3), 1e-15);
}
END_TEST

START_TEST(phong_exponent)
{
    /* l along n, v at 60 degrees from it: h lies at 30 degrees, so the highlight is
     * ks I cos(30)^p = 0.3 * 0.8660254^10 = 0.3 * 0.2373046875 for p = 10. */
    Material shiny = {.specular = {0.3, 0.3, 0.3}, .phong = 10};
    Incident in = from(vec3(0, 1, 0), color(1, 1, 1));
    Color c = shade_blinn_phong(&shiny, vec3(0, 1, 0), vec3(sin(M_PI / 3), cos(M_PI / 3), 0), &in);
    ck_assert_double_eq_tol(c.r, 0.3 * 0.2373046875, 1e-15);
}
END_TEST

START_TEST(light_behind_the_surface_gives_nothing)
{
    /* Not even a highlight, although h may still lean towards n. */
    Incident below = from(vec3(0.2, -1, 0), color(5, 5, 5));
    Color c =
        shade_blinn_phong(&red_glossy, vec3(0, 1, 0), vec3_normalize(vec3(-1, 0.1, 0)), &below);
    ck_assert_color_near(c, color(0, 0, 0), 0);
    Incident grazing = from(vec3(1, 0, 0), color(5, 5, 5));
    c = shade_blinn_phong(&red_glossy, vec3(0, 1, 0), vec3(0, 1, 0), &grazing);
    ck_assert_color_near(c, color(0, 0, 0), 0);
}
END_TEST

START_TEST(point_light_falloff)
{
    Light bulb = {.kind = LIGHT_POINT, .position = {0, 4, 0}, .color = {8, 8, 8}};
    /* Without falloff, the light's colour at any distance. */
    Incident near = light_incident(&bulb, vec3(0, 2, 0), false);
    ck_assert_color_near(near.radiance, color(8, 8, 8), 0);
    ck_assert_vec3_near(near.dir, vec3(0, 1, 0), 0);
    ck_assert_double_eq(near.distance, 2);
    /* With it, 8 / 2^2 = 2 at distance 2, and four times that at half the distance. */
    Incident at2 = light_incident(&bulb, vec3(0, 2, 0), true);
    Incident at1 = light_incident(&bulb, vec3(0, 3, 0), true);
    ck_assert_color_near(at2.radiance, color(2, 2, 2), 0);
    ck_assert_color_near(at1.radiance, color_scale(at2.radiance, 4), 0);
}
END_TEST

START_TEST(directional_light)
{
    /* It shines along v = (0,-1,0): light arrives from +y, from infinitely far, never fading. */
    Light sun = {.kind = LIGHT_DIRECTIONAL, .direction = {0, -1, 0}, .color = {1, 0.5, 0.25}};
    Incident in = light_incident(&sun, vec3(100, 7, -3), true);
    ck_assert_vec3_near(in.dir, vec3(0, 1, 0), 0);
    ck_assert(isinf(in.distance));
    ck_assert_color_near(in.radiance, color(1, 0.5, 0.25), 0);
}
END_TEST

START_TEST(area_light_is_a_point_at_its_centre)
{
    Light panel = {.kind = LIGHT_AREA,
                   .position = {0, 3, 4},
                   .direction = {0, -1, 0},
                   .size = 2,
                   .color = {1, 1, 1}};
    Incident in = light_incident(&panel, vec3(0, 0, 0), false);
    ck_assert_vec3_near(in.dir, vec3(0, 0.6, 0.8), 1e-15);
    ck_assert_double_eq(in.distance, 5);
}
END_TEST

START_TEST(a_light_at_the_point_lights_nothing)
{
    Light bulb = {.kind = LIGHT_POINT, .position = {1, 1, 1}, .color = {8, 8, 8}};
    Incident in = light_incident(&bulb, vec3(1, 1, 1), true);
    ck_assert_color_near(in.radiance, color(0, 0, 0), 0);
    Color c = shade_blinn_phong(&red_glossy, vec3(0, 1, 0), vec3(0, 1, 0), &in);
    ck_assert(color_is_finite(c));
    ck_assert_color_near(c, color(0, 0, 0), 0);
}
END_TEST

START_TEST(lights_add_up)
{
    /* Two unit lights straight above a matte floor: twice kd. */
    Light lights[] = {{.kind = LIGHT_POINT, .position = {0, 5, 0}, .color = {1, 1, 1}},
                      {.kind = LIGHT_DIRECTIONAL, .direction = {0, -1, 0}, .color = {1, 1, 1}}};
    Material matte = {.diffuse = {0.25, 0.5, 0.75}};
    Scene scene = {.materials = &matte, .material_count = 1, .lights = lights, .light_count = 2};
    Hit hit = {.t = 1, .point = {0, 0, 0}, .normal = {0, 1, 0}, .kind = SURFACE_PLANE};
    Color c = shade_direct_radiance(&scene, &hit, ray(vec3(0, 1, 0), vec3(0, -1, 0)), false);
    ck_assert_color_near(c, color(0.5, 1, 1.5), 1e-15);
}
END_TEST

START_TEST(shading_normal_faces_the_ray)
{
    Hit front = {.normal = {0, 1, 0}, .back_face = false, .kind = SURFACE_TRIANGLE};
    Hit back = {.normal = {0, 1, 0}, .back_face = true, .kind = SURFACE_TRIANGLE};
    Hit inside = {.normal = {0, 1, 0}, .back_face = true, .kind = SURFACE_SPHERE};
    ck_assert_vec3_near(shade_normal(&front), vec3(0, 1, 0), 0);
    ck_assert_vec3_near(shade_normal(&back), vec3(0, -1, 0), 0);
    ck_assert(!shade_shows_back_face(&front));
    ck_assert(shade_shows_back_face(&back));
    ck_assert(!shade_shows_back_face(&inside));
}
END_TEST

START_TEST(back_faces_are_lit_yellow)
{
    /* The back of a floor triangle, seen and lit from below by a unit light straight
     * under it: yellow diffuse, kd = (1, 1, 0), no highlight, n.l = 1. */
    Light below = {.kind = LIGHT_POINT, .position = {0, -5, 0}, .color = {1, 1, 1}};
    Material glossy_red = {.diffuse = {1, 0, 0}, .specular = {1, 1, 1}, .phong = 10};
    Scene scene = {
        .materials = &glossy_red, .material_count = 1, .lights = &below, .light_count = 1};
    Hit back = {.t = 1, .normal = {0, 1, 0}, .back_face = true, .kind = SURFACE_TRIANGLE};
    Ray from_below = ray(vec3(0, -1, 0), vec3(0, 1, 0));
    ck_assert_color_near(shade_direct_radiance(&scene, &back, from_below, false),
                         color(1, 1, 0), 1e-15);
    /* --two-sided: the triangle's own material, highlight included (n.h = 1). */
    ck_assert_color_near(shade_direct_radiance(&scene, &back, from_below, true),
                         color(2, 1, 1), 1e-15);
}
END_TEST

/* The shading tests. */
static Suite *shade_suite(void)
{
    Suite *s = suite_create("shade");
    TCase *bp = tcase_create("blinn-phong");
    tcase_add_test(bp, light_straight_above_gives_kd_I);
    tcase_add_test(bp, specular_peak_at_the_mirror_direction);
    tcase_add_test(bp, phong_exponent);
    tcase_add_test(bp, light_behind_the_surface_gives_nothing);
    tcase_add_test(bp, lights_add_up);
    tcase_add_test(bp, shading_normal_faces_the_ray);
    tcase_add_test(bp, back_faces_are_lit_yellow);
    suite_add_tcase(s, bp);
    TCase *lights = tcase_create("lights");
    tcase_add_test(lights, point_light_falloff);
    tcase_add_test(lights, directional_light);
    tcase_add_test(lights, area_light_is_a_point_at_its_centre);
    tcase_add_test(lights, a_light_at_the_point_lights_nothing);
    suite_add_tcase(s, lights);
    return s;
}

TEST_MAIN(shade_suite)
