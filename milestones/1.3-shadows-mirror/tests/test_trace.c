/* test_trace.c: the recursive radiance: mirrors, their depth limit, back faces, the background. */
#include "direct.h"
#include "secondary.h"
#include "trace.h"
#include "testing.h"

/* Two ideal mirrors facing each other: z = 0 facing +z and z = 10 facing -z. */
static Material mirror = {.mirror = {1, 1, 1}};
static Plane facing[] = {{.normal = {0, 0, 1}, .d = 0}, {.normal = {0, 0, -1}, .d = 10}};

/* A tracer over scene with the default offset and the given depth limit. */
static Tracer tracer(const Scene *scene, int max_depth)
{
    return (Tracer){.scene = scene,
                    .surfaces = surfaces_brute_force(scene),
                    .max_depth = max_depth,
                    .offset = SECONDARY_OFFSET,
                    .hooks = &direct_hooks};
}

START_TEST(facing_mirrors_stop_at_the_depth_limit)
{
    Scene scene = {.materials = &mirror, .material_count = 1, .planes = facing, .plane_count = 2};
    int limits[] = {0, 1, 5, 20, 100};
    for (int k = 0; k < 5; k++) {
        Tracer tr = tracer(&scene, limits[k]);
        RayStats stats = {{0}};
    Path path = {.stats = &stats};
        /* Straight at one mirror: every bounce comes back along the axis. */
        Color c = trace_radiance(&tr, ray(vec3(0, 0, 5), vec3(0, 0, 1)), 0, &path);
        ck_assert_int_eq(stats.rays[RAY_REFLECTED], limits[k]);
        ck_assert(color_is_finite(c));
        ck_assert_color_near(c, color(0, 0, 0), 0); /* no light anywhere */
    }
}
END_TEST

START_TEST(a_mirror_shows_km_times_what_it_faces)
{
    /* A floor mirror (km = 0.5, 0.25, 1; no kd or ks) at y = 0 and a matte wall at x = 10
     * facing -x (kd = 0.8) lit head-on by a directional light of 1 and an ambient of 0.1.
     * The wall's radiance is kd (ambient + I cos 0) = 0.8 * 1.1 = 0.88; the floor adds
     * only km * 0.88, plus kd ambient = 0 of its own. */
    Material materials[] = {{.mirror = {0.5, 0.25, 1}}, {.diffuse = {0.8, 0.8, 0.8}}};
    Plane planes[] = {{.normal = {0, 1, 0}, .d = 0, .material = 0},
                      {.normal = {-1, 0, 0}, .d = 10, .material = 1}};
    Light sun = {.kind = LIGHT_DIRECTIONAL, .direction = {1, 0, 0}, .color = {1, 1, 1}};
    Scene scene = {.materials = materials,
                   .material_count = 2,
                   .planes = planes,
                   .plane_count = 2,
                   .lights = &sun,
                   .light_count = 1,
                   .ambient = {0.1, 0.1, 0.1}};
    Tracer tr = tracer(&scene, 20);
    RayStats stats = {{0}};
    Path path = {.stats = &stats};
    /* 45 degrees down onto the floor at (5, 0, 0), reflected 45 degrees up to the wall. */
    Ray r = ray(vec3(0, 5, 0), vec3_normalize(vec3(1, -1, 0)));
    Color c = trace_radiance(&tr, r, 0, &path);
    ck_assert_color_near(c, color(0.44, 0.22, 0.88), 1e-15);
    ck_assert_int_eq(stats.rays[RAY_REFLECTED], 1);
    /* One shadow ray, at the wall: the sun shines along +x, parallel to the floor, so
     * the floor gets n.l = 0 and no shadow ray. */
    ck_assert_int_eq(stats.rays[RAY_SHADOW], 1);
}
END_TEST

START_TEST(no_reflected_ray_when_km_is_zero)
{
    Material matte = {.diffuse = {0.5, 0.5, 0.5}};
    Scene scene = {.materials = &matte, .material_count = 1, .planes = facing, .plane_count = 2};
    Tracer tr = tracer(&scene, 20);
    RayStats stats = {{0}};
    Path path = {.stats = &stats};
    trace_radiance(&tr, ray(vec3(0, 0, 5), vec3(0, 0, 1)), 0, &path);
    ck_assert_int_eq(stats.rays[RAY_REFLECTED], 0);
}
END_TEST

START_TEST(back_faces_are_lit_yellow_in_mirrors_too)
{
    /* The mirror floor reflects the ray onto the back of a triangle, which a sun lights
     * from our side, straight on; an ambient light of 0.4 lights everything. */
    Material materials[] = {{.mirror = {0.5, 0.5, 0.5}}, {.diffuse = {1, 1, 1}}};
    Plane floor = {.normal = {0, 1, 0}, .d = 0, .material = 0};
    /* The triangle in the plane x = 10, counterclockwise seen from +x: its back faces us. */
    Vec3 corners[] = {{10, 0, -5}, {10, 10, 0}, {10, 0, 5}};
    Face wall = {.corner = {0, 1, 2}, .material = 1};
    Light sun = {.kind = LIGHT_DIRECTIONAL, .direction = {1, 0, 0}, .color = {1, 1, 1}};
    Scene scene = {.materials = materials,
                   .material_count = 2,
                   .planes = &floor,
                   .plane_count = 1,
                   .vertices = corners,
                   .vertex_count = 3,
                   .triangles = &wall,
                   .triangle_count = 1,
                   .lights = &sun,
                   .light_count = 1,
                   .ambient = {0.4, 0.4, 0.4}};
    Tracer tr = tracer(&scene, 20);
    RayStats stats = {{0}};
    Path path = {.stats = &stats};
    Ray r = ray(vec3(0, 5, 0), vec3_normalize(vec3(1, -1, 0)));
    /* The back is yellow and diffuse, kd = (1, 1, 0): km (kd (sun cos 0 + ambient)). */
    ck_assert_color_near(trace_radiance(&tr, r, 0, &path), color(0.7, 0.7, 0), 1e-15);
    /* Under fall2016 the ambient light counts where camera rays hit only: not in mirrors. */
    scene.convention = CONVENTION_FALL2016;
    ck_assert_color_near(trace_radiance(&tr, r, 0, &path), color(0.5, 0.5, 0), 1e-15);
    /* With --two-sided the back has the triangle's own white material. */
    scene.convention = CONVENTION_LECTURE;
    tr.two_sided = true;
    ck_assert_color_near(trace_radiance(&tr, r, 0, &path), color(0.7, 0.7, 0.7), 1e-15);
}
END_TEST

START_TEST(background_is_black)
{
    Scene scene = {.materials = &mirror, .material_count = 1};
    Tracer tr = tracer(&scene, 20);
    RayStats stats = {{0}};
    Path path = {.stats = &stats};
    ck_assert_color_near(trace_radiance(&tr, ray(vec3(0, 0, 0), vec3(0, 1, 0)), 0, &path),
                         color(0, 0, 0), 0);
}
END_TEST

/* The tracer's tests. */
static Suite *trace_suite(void)
{
    Suite *s = suite_create("trace");
    TCase *tc = tcase_create("recursion");
    tcase_add_test(tc, facing_mirrors_stop_at_the_depth_limit);
    tcase_add_test(tc, a_mirror_shows_km_times_what_it_faces);
    tcase_add_test(tc, no_reflected_ray_when_km_is_zero);
    tcase_add_test(tc, back_faces_are_lit_yellow_in_mirrors_too);
    tcase_add_test(tc, background_is_black);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(trace_suite)
