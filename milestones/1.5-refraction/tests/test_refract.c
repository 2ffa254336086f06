/* test_refract.c: the radiance through glass on tiny scenes worked out by hand, and glass shadows.
 */
#include "light.h"
#include "refract.h"
#include "secondary.h"
#include "transmit.h"
#include "testing.h"

#define PI 3.14159265358979323846

/* A Refractor over scene and its tracer by brute force, with the default offset and the
 * given hooks; every ray is followed to the depth limit (--min-weight 0). */
static Tracer refractor(Refractor *rf, const Scene *scene, int max_depth, FresnelModel fresnel,
                        const TracerHooks *hooks)
{
    Options opts;
    cli_defaults(&opts, refract_part_options);
    cli_set(&opts, "max-depth", OPTION_INT)->whole = max_depth;
    cli_set(&opts, "min-weight", OPTION_NUMBER)->number = 0;
    cli_set(&opts, "fresnel", OPTION_TEXT)->text = fresnel == FRESNEL_EXACT ? "exact" : "schlick";
    ck_assert(refract_init(rf, scene, &opts));
    return tracer_make(scene, surfaces_brute_force(scene), &opts, hooks, rf);
}

/* Returns the radiance along the camera ray r, as the Refractor's tracer finds it. */
static Color radiance_of(const Refractor *rf, const Tracer *tr, Ray r, Path *path)
{
    return refract_trace(rf, tr, r, RAY_PRIMARY, 0, 1, path);
}

/* Where the rays that reach material RECORDED at depth RECORDED_DEPTH arrive: a light
 * hook, called at every hit of a scene with one (dark) light, that notes the hit. */
static int recorded_material, recorded_depth, recorded_count;
static Vec3 recorded_point, recorded_dir;

/* The recording hook: notes every hit on recorded_material at recorded_depth; the light
 * adds nothing. */
static Color record_light(const void *ctx, const Tracer *tr, const Hit *hit, Ray r,
                          const Light *light, int depth, Path *path)
{
    (void)ctx, (void)tr, (void)light, (void)path;
    if (depth == recorded_depth && hit->material == recorded_material) {
        recorded_point = hit->point;
        recorded_dir = r.dir;
        recorded_count++;
    }
    return color(0, 0, 0);
}
static const TracerHooks recording = {.light = record_light, .through = transmit_light};

/* Glass of index 1.5 absorbing (0.5, 0.25, 0.8) a unit; a white matte wall. */
static Material materials[] = {
    {.ior = 1.5, .attenuation = {0.5, 0.25, 0.8}},
    {.diffuse = {1, 1, 1}, .attenuation = {1, 1, 1}},
};

START_TEST(through_the_centre_of_a_sphere)
{
    /* A sphere of radius 2 at the origin, a wall z = -10 facing +z lit by an ambient light
     * of 0.3: the wall sends W = 0.3 back everywhere. A ray along -z through the centre
     * meets both surfaces head-on: it goes straight on, keeps 1 - R0 at each, and
     * crosses 2r = 4 units of glass. */
    Sphere ball = {.center = {0, 0, 0}, .radius = 2, .material = 0};
    Plane wall = {.normal = {0, 0, 1}, .d = 10, .material = 1};
    Light dark = {.kind = LIGHT_POINT}; /* only to be noted at every hit (record_light) */
    Scene scene = {.materials = materials,
                   .material_count = 2,
                   .spheres = &ball,
                   .sphere_count = 1,
                   .planes = &wall,
                   .plane_count = 1,
                   .lights = &dark,
                   .light_count = 1,
                   .ambient = {0.3, 0.3, 0.3}};
    Ray r = ray(vec3(0, 0, 10), vec3(0, 0, -1));
    double t = 1 - 0.04; /* 1 - R0 at n = 1.5, by either model */
    Color a4 = color(pow(0.5, 4), pow(0.25, 4), pow(0.8, 4));
    for (int model = 0; model < 2; model++) {
        /* Depth 2: in, out, and the wall; the ray reflected inside dies at the budget. */
        Refractor rf;
        Tracer tr = refractor(&rf, &scene, 2, (FresnelModel)model, &recording);
        recorded_material = 1, recorded_depth = 2, recorded_count = 0;
        RayStats stats = {{0}};
        Path path = {.stats = &stats};
        Color c = radiance_of(&rf, &tr, r, &path);
        /* Exactly, but for the secondary rays' offsets: each ray starts 2^-32 times the
         * coordinates (10) off the surface, so s is short by about 2e-9. */
        ck_assert_color_near(c, color_scale(a4, t * t * 0.3), 1e-10);
        ck_assert_double_eq_tol(c.r / (t * t * 0.3), pow(0.5, 2 * ball.radius), 2e-9);
        ck_assert_int_eq(recorded_count, 1);
        ck_assert_vec3_near(recorded_point, vec3(0, 0, -10), 1e-12);
        ck_assert_vec3_near(recorded_dir, vec3(0, 0, -1), 0);
        ck_assert_int_eq(stats.rays[RAY_REFRACTED], 2);
        ck_assert_int_eq(stats.rays[RAY_REFLECTED], 2);
        /* With room for every bounce, light goes back and forth inside: a geometric
         * series, (1 - R)^2 a^4 W / (1 - R^2 a^8). */
        tr = refractor(&rf, &scene, 200, (FresnelModel)model, &refract_hooks);
        c = radiance_of(&rf, &tr, r, &path);
        Color a8 = color_mul(a4, a4);
        Color expected = color(a4.r / (1 - 0.0016 * a8.r), a4.g / (1 - 0.0016 * a8.g),
                               a4.b / (1 - 0.0016 * a8.b));
        ck_assert_color_near(c, color_scale(expected, t * t * 0.3), 1e-10);
    }
}
END_TEST

/* Returns how far the ray that leaves a slab of glass (index n, thickness h, between the
 * planes y = 0 and y = -h) is shifted sideways from the ray that entered at theta, as the
 * tracer finds it; checks that the direction is unchanged. */
static double slab_shift(double n, double h, double theta, FresnelModel model)
{
    Material m[] = {{.ior = n, .attenuation = {1, 1, 1}},
                    {.diffuse = {1, 1, 1}, .attenuation = {1, 1, 1}}};
    /* The top faces up (air above), the bottom faces down (air below): p.N + d = 0. */
    Plane planes[] = {{.normal = {0, 1, 0}, .d = 0, .material = 0},
                      {.normal = {0, -1, 0}, .d = -h, .material = 0},
                      {.normal = {0, 1, 0}, .d = h + 5, .material = 1}};
    Light dark = {.kind = LIGHT_POINT}; /* only to be noted at every hit (record_light) */
    Scene scene = {.materials = m,
                   .material_count = 2,
                   .planes = planes,
                   .plane_count = 3,
                   .lights = &dark,
                   .light_count = 1};
    Refractor rf;
    Tracer tr = refractor(&rf, &scene, 10, model, &recording);
    recorded_material = 1, recorded_depth = 2, recorded_count = 0;
    Vec3 o = vec3(0, 10, 0), d = vec3(sin(theta), -cos(theta), 0);
    RayStats stats = {{0}};
    Path path = {.stats = &stats};
    radiance_of(&rf, &tr, ray(o, d), &path);
    ck_assert_int_eq(recorded_count, 1);
    /* Both faces bend the ray by the same angle, the other way: it leaves parallel. */
    ck_assert_vec3_near(recorded_dir, d, 1e-14);
    /* The distance of the floor point from the line the ray came in on. */
    return vec3_length(vec3_cross(vec3_sub(recorded_point, o), d));
}

START_TEST(a_slab_shifts_a_ray_sideways)
{
    /* Inside, the ray runs h / cos(theta_t) units, at theta - theta_t to its old line:
     * it comes out shifted by h sin(theta - theta_t) / cos(theta_t). */
    double indices[] = {1.33, 1.5, 2.4};
    for (int k = 0; k < 3; k++)
        for (double deg = 0; deg <= 80; deg += 20) {
            double n = indices[k], h = 3, theta = deg * PI / 180;
            double theta_t = asin(sin(theta) / n);
            double expected = h * sin(theta - theta_t) / cos(theta_t);
            /* To within the offsets of the secondary rays, 2^-32 times coordinates of 10 to 60. */
            ck_assert_double_eq_tol(slab_shift(n, h, theta, FRESNEL_SCHLICK), expected, 3e-8);
            ck_assert_double_eq_tol(slab_shift(n, h, theta, FRESNEL_EXACT), expected, 3e-8);
        }
    /* By hand at 60 degrees into n = 1.5: sin(theta_t) = 0.57735, theta_t = 35.26
     * degrees, shift 3 sin(24.74 deg) / cos(35.26 deg) = 3 (0.41842 / 0.81650) = 1.5374. */
    ck_assert_double_eq_tol(slab_shift(1.5, 3, PI / 3, FRESNEL_SCHLICK), 1.5374, 1e-4);
}
END_TEST

START_TEST(total_internal_reflection_in_the_tracer)
{
    /* Glass below the plane y = 0 (facing up); a ray starts inside, under the surface,
     * at an angle from the normal just below or just above the critical angle. */
    Material glass = {.ior = 1.5, .attenuation = {1, 1, 1}};
    Plane surface = {.normal = {0, 1, 0}, .d = 0, .material = 0};
    Scene scene = {.materials = &glass, .material_count = 1, .planes = &surface, .plane_count = 1};
    Refractor rf;
    Tracer tr = refractor(&rf, &scene, 1, FRESNEL_SCHLICK, &refract_hooks);
    double critical = asin(1 / 1.5);
    double angles[] = {critical - 1e-6, critical + 1e-6};
    for (int k = 0; k < 2; k++) {
        RayStats stats = {{0}};
        Path path = {.stats = &stats};
        Ray r = ray(vec3(0, -1, 0), vec3(sin(angles[k]), cos(angles[k]), 0));
        Color c = radiance_of(&rf, &tr, r, &path);
        ck_assert(color_is_finite(c));
        ck_assert_int_eq(stats.rays[RAY_REFLECTED], 1);
        ck_assert_int_eq(stats.rays[RAY_REFRACTED], k == 0 ? 1 : 0);
    }
}
END_TEST

/* Returns the radiance along r in a white furnace: inside a matte sphere of radius 100
 * that sends W = 0.5 back everywhere (kd 1, ambient 0.5), holding spheres of glass. */
static Color furnace_of(Ray r, Material glass, FresnelModel model, int max_depth, double min_weight,
                        RayStats *stats)
{
    Material m[] = {{.diffuse = {1, 1, 1}, .attenuation = {1, 1, 1}}, glass};
    Sphere spheres[] = {{.center = {0, 0, 0}, .radius = 100, .material = 0},
                        {.center = {0, 0, 0}, .radius = 10, .material = 1},
                        {.center = {25, 5, -3}, .radius = 7, .material = 1}};
    Scene scene = {.materials = m,
                   .material_count = 2,
                   .spheres = spheres,
                   .sphere_count = 3,
                   .ambient = {0.5, 0.5, 0.5}};
    Refractor rf;
    Tracer tr = refractor(&rf, &scene, max_depth, model, &refract_hooks);
    rf.min_weight = min_weight;
    Path path = {.stats = stats};
    return radiance_of(&rf, &tr, r, &path);
}

/* The same, with clear or absorbing glass of index ior. */
static Color furnace(Ray r, Color attenuation, double ior, FresnelModel model, int max_depth,
                     double min_weight, RayStats *stats)
{
    Material glass = {.ior = ior, .attenuation = attenuation};
    return furnace_of(r, glass, model, max_depth, min_weight, stats);
}

START_TEST(clear_glass_in_a_furnace_is_invisible)
{
    /* Where everything sends back the same W, clear glass that loses nothing (R + T = 1 at
     * every surface, no absorption) must send back W too, whatever it bends: energy. */
    double indices[] = {1.33, 1.5, 2.4};
    for (int k = 0; k < 3; k++)
        for (int model = 0; model < 2; model++)
            for (double x = -34; x < 34; x += 0.77) {
                RayStats stats = {{0}};
                Ray r = ray(vec3(x * 0.3, -2, 50), vec3_normalize(vec3(x, 0.1 * x, -50)));
                Color c =
                    furnace(r, color(1, 1, 1), indices[k], (FresnelModel)model, 60, 0, &stats);
                ck_assert_color_near(c, color(0.5, 0.5, 0.5), 1e-9);
            }
    /* Absorbing glass sends back less, and more the longer the way through it. */
    RayStats stats = {{0}};
    Color centre = furnace(ray(vec3(0, 0, 50), vec3(0, 0, -1)), color(0.9, 0.9, 0.9), 1.5,
                           FRESNEL_EXACT, 60, 0, &stats);
    Color edge = furnace(ray(vec3(9, 0, 50), vec3(0, 0, -1)), color(0.9, 0.9, 0.9), 1.5,
                         FRESNEL_EXACT, 60, 0, &stats);
    ck_assert(centre.r < edge.r && edge.r < 0.5);
}
END_TEST

START_TEST(rays_too_faint_to_see_are_not_followed)
{
    /* --min-weight's default, 2^-16: the same picture to well within a PNG's step of
     * 1/255, for a fraction of the rays. */
    RayStats all = {{0}}, some = {{0}};
    for (double x = -30; x < 30; x += 1.3) {
        Ray r = ray(vec3(x * 0.3, -2, 50), vec3_normalize(vec3(x, 0.1 * x, -50)));
        Color exact = furnace(r, color(1, 0.9, 0.8), 2.4, FRESNEL_EXACT, 60, 0, &all);
        Color cut = furnace(r, color(1, 0.9, 0.8), 2.4, FRESNEL_EXACT, 60, 0x1p-16, &some);
        ck_assert_color_near(cut, exact, 1e-4);
        ck_assert(cut.r <= exact.r && cut.g <= exact.g && cut.b <= exact.b);
    }
    ck_assert_uint_lt(3 * render_total_rays(&some), render_total_rays(&all));
}
END_TEST

START_TEST(the_depth_budget_is_shared)
{
    /* Head-on into the furnace's central glass sphere at depth limits 0, 1 and 2. */
    Ray r = ray(vec3(0, 0, 50), vec3(0, 0, -1));
    RayStats stats = {{0}};
    /* 0: no reflected or refracted ray; the glass itself is black. */
    Color c = furnace(r, color(1, 1, 1), 1.5, FRESNEL_SCHLICK, 0, 0, &stats);
    ck_assert_color_near(c, color(0, 0, 0), 0);
    ck_assert_int_eq(stats.rays[RAY_REFLECTED] + stats.rays[RAY_REFRACTED], 0);
    /* 1: R0 of the wall behind the camera, and the refracted ray ends black inside. */
    c = furnace(r, color(1, 1, 1), 1.5, FRESNEL_SCHLICK, 1, 0, &stats);
    ck_assert_color_near(c, color(0.02, 0.02, 0.02), 1e-15);
    ck_assert_int_eq(stats.rays[RAY_REFLECTED], 1);
    ck_assert_int_eq(stats.rays[RAY_REFRACTED], 1);
    /* 2: also (1 - R0)^2 W out of the far side; the ray reflected inside ends black. */
    c = furnace(r, color(1, 1, 1), 1.5, FRESNEL_SCHLICK, 2, 0, &stats);
    ck_assert_color_near(c, color(0.4808, 0.4808, 0.4808), 1e-12);
    /* However deep, nothing but finite numbers. */
    for (int depth = 0; depth < 40; depth += 3) {
        c = furnace(ray(vec3(7, 3, 50), vec3(0, 0, -1)), color(0.1, 0.5, 1), 2.4, FRESNEL_EXACT,
                    depth, 0, &stats);
        ck_assert(color_is_finite(c) && c.r >= 0 && c.r <= 0.5 + 1e-12);
    }
}
END_TEST

/* The depth at which weigh_light sends white back from every hit; above it, nothing. */
static int weighed_depth;

/* A light hook under which the radiance along a ray is the sum, over the rays at depth
 * weighed_depth below it (the depth limit, where every ray ends), of their weights: the
 * products of the k_m, 1 - max(k_m), R and 1 - R along their paths (no other light, no
 * absorption: a = 1). */
static Color weigh_light(const void *ctx, const Tracer *tr, const Hit *hit, Ray r,
                         const Light *light, int depth, Path *path)
{
    (void)ctx, (void)tr, (void)hit, (void)r, (void)light, (void)path;
    return depth == weighed_depth ? color(1, 1, 1) : color(0, 0, 0);
}
static const TracerHooks weighing = {.light = weigh_light, .through = transmit_light};

START_TEST(a_mirror_of_glass_splits_no_more_than_it_gets)
{
    /* A ball both mirror and glass (k_m, n = 1.5) inside a closed room: every ray meets
     * something, so the rays at depth d carry all of the weight that reaches them. The
     * mirror takes k_m, the glass 1 - max(k_m): at every depth the weights add up to at
     * most 1 in every channel, where k_m + R + (1 - R) = 1 + k_m a hit made them grow as
     * (1 + k_m)^d. A grey k_m loses nothing: the first split adds up to exactly 1. */
    Color coatings[] = {{0.5, 0.5, 0.5}, {1, 1, 1}, {0.9, 0.2, 0.5}, {0, 0, 0}};
    for (int k = 0; k < 4; k++) {
        Material m[] = {{.diffuse = {1, 1, 1}, .attenuation = {1, 1, 1}},
                        {.mirror = coatings[k], .ior = 1.5, .attenuation = {1, 1, 1}}};
        Sphere spheres[] = {{.center = {0, 0, 0}, .radius = 100, .material = 0},
                            {.center = {0, 0, 0}, .radius = 10, .material = 1},
                            {.center = {25, 5, -3}, .radius = 7, .material = 1}};
        Light white = {.kind = LIGHT_POINT}; /* weigh_light's, at every hit */
        Scene scene = {.materials = m,
                       .material_count = 2,
                       .spheres = spheres,
                       .sphere_count = 3,
                       .lights = &white,
                       .light_count = 1};
        for (int depth = 1; depth <= 9; depth++) {
            Refractor rf;
            Tracer tr = refractor(&rf, &scene, depth, FRESNEL_EXACT, &weighing);
            weighed_depth = depth;
            RayStats stats = {{0}};
            Path path = {.stats = &stats};
            Ray r = ray(vec3(3, 1, 50), vec3_normalize(vec3(0.1, 0, -1)));
            Color w = radiance_of(&rf, &tr, r, &path);
            ck_assert_msg(w.r <= 1 + 1e-12 && w.g <= 1 + 1e-12 && w.b <= 1 + 1e-12,
                          "coating %d, depth %d: weights add up to (%g, %g, %g)", k, depth, w.r,
                          w.g, w.b);
            ck_assert(w.r >= 0 && w.g >= 0 && w.b >= 0);
            if (depth == 1) {
                /* k_m + (1 - max(k_m)) (R + 1 - R), channel by channel. */
                Color km = coatings[k];
                double glass = 1 - fmax(km.r, fmax(km.g, km.b));
                ck_assert_color_near(w, color(km.r + glass, km.g + glass, km.b + glass), 1e-12);
            }
        }
    }
}
END_TEST

START_TEST(a_mirror_of_glass_in_a_furnace_sends_back_what_it_gets)
{
    /* In the white furnace, half-silvered clear glass sends back W = 0.5, as a mirror or
     * clear glass alone does, but for the rays pruned below a weight of 2^-22: they lose
     * 3 x 10^-4 of W at most here (2 x 10^-3 at --min-weight's default, 2^-16). */
    Material half_silvered = {.mirror = {0.5, 0.5, 0.5}, .ior = 1.5, .attenuation = {1, 1, 1}};
    for (double x = -30; x < 30; x += 1.7) {
        RayStats stats = {{0}};
        Ray r = ray(vec3(x * 0.3, -2, 50), vec3_normalize(vec3(x, 0.1 * x, -50)));
        Color c = furnace_of(r, half_silvered, FRESNEL_EXACT, 60, 0x1p-22, &stats);
        ck_assert_color_near(c, color(0.5, 0.5, 0.5), 1e-3);
        ck_assert(c.r <= 0.5 + 1e-12);
        /* The weights of a depth add up to at most 1, so at most 2^22 rays of a depth
         * count 2^-22 or more: the work is bounded (and in fact far smaller). */
        ck_assert_uint_lt(render_total_rays(&stats), 60 * 0x1p22);
    }
}
END_TEST

/* The fraction of a point light at (0, 10, 0) that reaches the floor point at the origin,
 * past a sphere of radius 1 at (0, 2, 0) of material ball. */
static Color light_through(Material ball, FresnelModel model, RayStats *stats)
{
    Material m[] = {{.diffuse = {1, 1, 1}, .attenuation = {1, 1, 1}}, ball};
    Sphere s = {.center = {0, 2, 0}, .radius = 1, .material = 1};
    Plane floor = {.normal = {0, 1, 0}, .d = 0, .material = 0};
    Light lamp = {.kind = LIGHT_POINT, .position = {0, 10, 0}, .color = {1, 1, 1}};
    Scene scene = {.materials = m,
                   .material_count = 2,
                   .spheres = &s,
                   .sphere_count = 1,
                   .planes = &floor,
                   .plane_count = 1,
                   .lights = &lamp,
                   .light_count = 1};
    Refractor rf;
    Tracer tr = refractor(&rf, &scene, 20, model, &refract_hooks);
    Hit hit = {
        .t = 1, .point = {0, 0, 0}, .normal = {0, 1, 0}, .material = 0, .kind = SURFACE_PLANE};
    Incident in = light_incident(&lamp, hit.point, false);
    Path path = {.stats = stats};
    return transmit_light(&rf, &tr, &hit,
                          ray(vec3(0, 1, 1), vec3_normalize(vec3(0, -1, -1))), &in, 0, &path);
}

START_TEST(shadows_of_glass_are_dimmed_not_dark)
{
    RayStats stats = {{0}};
    /* Opaque: no light at all, after one shadow ray. */
    Material opaque = {.diffuse = {1, 0, 0}, .attenuation = {1, 1, 1}};
    ck_assert_color_near(light_through(opaque, FRESNEL_SCHLICK, &stats), color(0, 0, 0), 0);
    ck_assert_int_eq(stats.rays[RAY_SHADOW], 1);
    /* Glass: straight up through the centre, head-on at both surfaces: (1 - R0)^2 a^2r. */
    Material glass = {.ior = 1.5, .attenuation = {0.5, 0.25, 1}};
    for (int model = 0; model < 2; model++) {
        Color got = light_through(glass, (FresnelModel)model, &stats);
        ck_assert_color_near(got, color_scale(color(0.25, 0.0625, 1), 0.96 * 0.96), 1e-9);
    }
    /* Index 1, no absorption: the exact equations let everything through, Schlick too
     * head-on (R0 = 0). */
    Material air = {.ior = 1, .attenuation = {1, 1, 1}};
    ck_assert_color_near(light_through(air, FRESNEL_EXACT, &stats), color(1, 1, 1), 1e-15);
    ck_assert_color_near(light_through(air, FRESNEL_SCHLICK, &stats), color(1, 1, 1), 1e-15);
}
END_TEST

START_TEST(the_inside_of_a_glass_mesh_keeps_its_material)
{
    /* The back of a glass triangle is the inside of a solid: its own material, the normal
     * turned to face the ray; the back of an opaque one stays part 1.2's back face. */
    Material m[] = {{.ior = 1.5, .attenuation = {1, 1, 1}}, {.diffuse = {1, 1, 1}}};
    Scene scene = {.materials = m, .material_count = 2};
    Hit back = {.normal = {0, 1, 0}, .back_face = true, .material = 0, .kind = SURFACE_TRIANGLE};
    Hit seen = refract_glass_hit(&scene, &back);
    ck_assert(!seen.back_face);
    ck_assert_vec3_near(seen.normal, vec3(0, -1, 0), 0);
    back.material = 1;
    seen = refract_glass_hit(&scene, &back);
    ck_assert(seen.back_face);
    ck_assert_vec3_near(seen.normal, vec3(0, 1, 0), 0);
}
END_TEST

/* The tracer's tests. */
static Suite *refract_suite(void)
{
    Suite *s = suite_create("refract");
    TCase *tc = tcase_create("glass");
    tcase_add_test(tc, through_the_centre_of_a_sphere);
    tcase_add_test(tc, a_slab_shifts_a_ray_sideways);
    tcase_add_test(tc, total_internal_reflection_in_the_tracer);
    tcase_add_test(tc, clear_glass_in_a_furnace_is_invisible);
    tcase_add_test(tc, rays_too_faint_to_see_are_not_followed);
    tcase_add_test(tc, the_depth_budget_is_shared);
    tcase_add_test(tc, a_mirror_of_glass_splits_no_more_than_it_gets);
    tcase_add_test(tc, a_mirror_of_glass_in_a_furnace_sends_back_what_it_gets);
    tcase_add_test(tc, shadows_of_glass_are_dimmed_not_dark);
    tcase_add_test(tc, the_inside_of_a_glass_mesh_keeps_its_material);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(refract_suite)
