/* test_direct.c: shadow rays and the ambient light. */
#include "direct.h"
#include "secondary.h"
#include "testing.h"

static Material materials[] = {{.diffuse = {0.5, 0.4, 0.2}}};

/* A tracer over a scene of the given spheres and lights, with the default offset. */
static Tracer tracer(Scene *scene)
{
    scene->materials = materials;
    scene->material_count = 1;
    return (Tracer){.scene = scene,
                    .surfaces = surfaces_brute_force(scene),
                    .max_depth = 20,
                    .offset = SECONDARY_OFFSET,
                    .hooks = &direct_hooks};
}

/* A hit on the floor y = 0 at the origin, seen from above. */
static const Hit floor_hit = {
    .t = 10, .point = {0, 0, 0}, .normal = {0, 1, 0}, .kind = SURFACE_PLANE};
static const Ray from_above = {{0, 10, 0}, {0, -1, 0}};

/* Tells whether the floor point is in the shadow of light, among spheres. */
static bool shadowed(Sphere *spheres, int count, Light light)
{
    Scene scene = {.spheres = spheres, .sphere_count = count, .lights = &light, .light_count = 1};
    Tracer tr = tracer(&scene);
    Incident in = light_incident(&light, floor_hit.point, false);
    RayStats stats = {{0}};
    Path path = {.stats = &stats};
    bool blocked = direct_in_shadow(&tr, &floor_hit, from_above, &in, 0, &path);
    ck_assert_int_eq(stats.rays[RAY_SHADOW], 1);
    return blocked;
}

START_TEST(sphere_between_point_and_light_blocks_it)
{
    Light bulb = {.kind = LIGHT_POINT, .position = {0, 10, 0}, .color = {1, 1, 1}};
    Sphere between = {.center = {0, 5, 0}, .radius = 1};
    ck_assert(shadowed(&between, 1, bulb));
    /* Off to the side by more than its radius: no shadow. */
    Sphere aside = {.center = {1.5, 5, 0}, .radius = 1};
    ck_assert(!shadowed(&aside, 1, bulb));
}
END_TEST

START_TEST(sphere_behind_the_light_or_the_point_does_not)
{
    Light bulb = {.kind = LIGHT_POINT, .position = {0, 10, 0}, .color = {1, 1, 1}};
    Sphere beyond_light = {.center = {0, 15, 0}, .radius = 1};
    ck_assert(!shadowed(&beyond_light, 1, bulb));
    Sphere below_floor = {.center = {0, -5, 0}, .radius = 1};
    ck_assert(!shadowed(&below_floor, 1, bulb));
    /* A sphere that encloses the light: its shell lies between, so it blocks. */
    Sphere around_light = {.center = {0, 10, 0}, .radius = 2};
    ck_assert(shadowed(&around_light, 1, bulb));
}
END_TEST

START_TEST(directional_light_blocked)
{
    /* It shines down along (-1, -1, 0): light arrives from (1, 1, 0)/sqrt 2, however far. */
    Light sun = {.kind = LIGHT_DIRECTIONAL,
                 .direction = vec3(-sqrt(0.5), -sqrt(0.5), 0),
                 .color = {1, 1, 1}};
    Sphere far_up_the_beam = {.center = {1000, 1000, 0}, .radius = 1};
    ck_assert(shadowed(&far_up_the_beam, 1, sun));
    Sphere off_the_beam = {.center = {1000, 1000, 5}, .radius = 1};
    ck_assert(!shadowed(&off_the_beam, 1, sun));
}
END_TEST

START_TEST(ambient_only_gives_kd_times_ambient)
{
    Scene scene = {.ambient = {0.2, 0.5, 1.0}};
    Tracer tr = tracer(&scene);
    RayStats stats = {{0}};
    Path path = {.stats = &stats};
    Color c = direct_radiance(&tr, &floor_hit, from_above, 0, &path);
    ck_assert_color_near(c, color(0.1, 0.2, 0.2), 0);
    ck_assert_int_eq(stats.rays[RAY_SHADOW], 0);
}
END_TEST

START_TEST(fall2016_ambient_only_where_camera_rays_hit)
{
    Scene scene = {.ambient = {0.2, 0.5, 1.0}, .convention = CONVENTION_FALL2016};
    Tracer tr = tracer(&scene);
    RayStats stats = {{0}};
    Path path = {.stats = &stats};
    ck_assert_color_near(direct_radiance(&tr, &floor_hit, from_above, 0, &path),
                         color(0.1, 0.2, 0.2), 0);
    ck_assert_color_near(direct_radiance(&tr, &floor_hit, from_above, 1, &path),
                         color(0, 0, 0), 0);
    scene.convention = CONVENTION_LECTURE;
    ck_assert_color_near(direct_radiance(&tr, &floor_hit, from_above, 3, &path),
                         color(0.1, 0.2, 0.2), 0);
}
END_TEST

START_TEST(shadowed_light_leaves_ambient_only)
{
    Light bulb = {.kind = LIGHT_POINT, .position = {0, 10, 0}, .color = {1, 1, 1}};
    Sphere between = {.center = {0, 5, 0}, .radius = 1};
    Scene scene = {.spheres = &between,
                   .sphere_count = 1,
                   .lights = &bulb,
                   .light_count = 1,
                   .ambient = {0.2, 0.2, 0.2}};
    Tracer tr = tracer(&scene);
    RayStats stats = {{0}};
    Path path = {.stats = &stats};
    ck_assert_color_near(direct_radiance(&tr, &floor_hit, from_above, 0, &path),
                         color(0.1, 0.08, 0.04), 1e-16);
    /* Without the sphere, kd (ambient + I cos 0) = kd * 1.2. */
    scene.sphere_count = 0;
    ck_assert_color_near(direct_radiance(&tr, &floor_hit, from_above, 0, &path),
                         color(0.6, 0.48, 0.24), 1e-15);
}
END_TEST

START_TEST(no_shadow_ray_for_a_light_behind_the_surface)
{
    Light below = {.kind = LIGHT_POINT, .position = {0, -10, 0}, .color = {1, 1, 1}};
    Scene scene = {.lights = &below, .light_count = 1};
    Tracer tr = tracer(&scene);
    RayStats stats = {{0}};
    Path path = {.stats = &stats};
    ck_assert_color_near(direct_radiance(&tr, &floor_hit, from_above, 0, &path), color(0, 0, 0), 0);
    ck_assert_int_eq(stats.rays[RAY_SHADOW], 0);
}
END_TEST

START_TEST(the_shadow_reaches_the_contact_point)
{
    /* A unit ball resting on the floor at the origin, the light straight above: the floor
     * 0.001 from the contact point is in shadow (the ball is 5e-7 above it there). A
     * shadow ray started too far off the floor would miss the ball: a bright gap. */
    Light bulb = {.kind = LIGHT_POINT, .position = {0, 10, 0}, .color = {1, 1, 1}};
    Sphere ball = {.center = {0, 1, 0}, .radius = 1};
    Scene scene = {.spheres = &ball, .sphere_count = 1, .lights = &bulb, .light_count = 1};
    Tracer tr = tracer(&scene);
    Hit near_contact = floor_hit;
    near_contact.point = vec3(0.001, 0, 0);
    Incident in = light_incident(&bulb, near_contact.point, false);
    RayStats stats = {{0}};
    Path path = {.stats = &stats};
    ck_assert(direct_in_shadow(&tr, &near_contact, from_above, &in, 0, &path));
}
END_TEST

START_TEST(no_light_leaks_through_a_thin_wall)
{
    /* A wall one millionth thick (two triangles, back to back) stands at x = 1 between a
     * light at x = 10 and the floor point 0.000001 in front of it. */
    Vec3 corners[] = {{1, -1, -1},        {1, -1, 1},       {1, 5, 0},
                      {1 + 1e-6, -1, -1}, {1 + 1e-6, 5, 0}, {1 + 1e-6, -1, 1}};
    Face wall[] = {{.corner = {0, 1, 2}}, {.corner = {3, 4, 5}}};
    Light bulb = {.kind = LIGHT_POINT, .position = {10, 0.5, 0}, .color = {1, 1, 1}};
    Scene scene = {.vertices = corners,
                   .vertex_count = 6,
                   .triangles = wall,
                   .triangle_count = 2,
                   .lights = &bulb,
                   .light_count = 1};
    Tracer tr = tracer(&scene);
    Hit behind = floor_hit;
    behind.point = vec3(1 - 1e-6, 0, 0);
    Incident in = light_incident(&bulb, behind.point, false);
    RayStats stats = {{0}};
    Path path = {.stats = &stats};
    ck_assert(direct_in_shadow(&tr, &behind, from_above, &in, 0, &path));
    /* And a point on the wall's lit face is not shadowed by the wall itself. */
    Hit on_face = {
        .t = 1, .point = {1 + 1e-6, 0.5, 0}, .normal = {1, 0, 0}, .kind = SURFACE_TRIANGLE};
    in = light_incident(&bulb, on_face.point, false);
    ck_assert(
        !direct_in_shadow(&tr, &on_face, ray(vec3(5, 0.5, 3), vec3(-1, 0, 0)), &in, 0, &path));
}
END_TEST

/* The direct-light tests. */
static Suite *direct_suite(void)
{
    Suite *s = suite_create("direct");
    TCase *tc = tcase_create("shadows and ambient");
    tcase_add_test(tc, sphere_between_point_and_light_blocks_it);
    tcase_add_test(tc, sphere_behind_the_light_or_the_point_does_not);
    tcase_add_test(tc, directional_light_blocked);
    tcase_add_test(tc, ambient_only_gives_kd_times_ambient);
    tcase_add_test(tc, fall2016_ambient_only_where_camera_rays_hit);
    tcase_add_test(tc, shadowed_light_leaves_ambient_only);
    tcase_add_test(tc, no_shadow_ray_for_a_light_behind_the_surface);
    tcase_add_test(tc, the_shadow_reaches_the_contact_point);
    tcase_add_test(tc, no_light_leaks_through_a_thin_wall);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(direct_suite)
