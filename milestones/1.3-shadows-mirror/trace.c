/* trace.c: the radiance along a ray, and the seams through which every ray is traced and told. */
#include "trace.h"

#include "direct.h"
#include "secondary.h"
#include "shade.h"
#include "world.h"

/* Part 1.3's radiance hook: trace_radiance, which needs no context. */
static Color trace_radiance_hook(const void *ctx, const Tracer *tr, Ray r, int depth, Path *path)
{
    (void)ctx;
    return trace_radiance(tr, r, depth, path);
}

/* Part 1.3's own hooks, with which every tracer starts: mirrors (trace_radiance), point
 * and directional lights (direct_light), shadows all or nothing (direct_through). */
const TracerHooks tracer_hooks = {
    .radiance = trace_radiance_hook, .light = direct_light, .through = direct_through};

/* Returns the tracer of scene, finding hits with surfaces, set up by the command line;
 * its hooks are part 1.3's own. */
Tracer tracer_make(const Scene *scene, Surfaces surfaces, const Options *opts)
{
    return (Tracer){.scene = scene,
                    .surfaces = surfaces,
                    .max_depth = cli_int(opts, "max-depth"),
                    .two_sided = cli_flag(opts, "two-sided"),
                    .offset = cli_number(opts, "ray-offset"),
                    .hooks = tracer_hooks,
                    .explain = opts->explain};
}

/* starter: todo */
/* Returns the radiance arriving along ray r: the light of the first surface it meets,
 * straight from the lights, plus k_m times the radiance along the mirror-reflected ray.
 * depth counts the reflections that led to r; primary rays have depth 0. */
Color trace_radiance(const Tracer *tr, Ray r, int depth, Path *path)
{
    Hit hit;
    if (!tracer_hit(tr, r, depth, &hit))
        return color(0, 0, 0); /* the black background */
    Color radiance = direct_radiance(tr, &hit, r, depth, path);

    /* An ideal mirror sends back k_m of what arrives from the mirror direction, which is
     * what a ray traced in that direction finds: the same question, one bounce later. */
    Color km = shade_material(tr->scene, &hit, tr->two_sided)->mirror;
    if (!color_is_black(km) && depth < tr->max_depth) {
        Vec3 dir = secondary_reflect(r.dir, shade_normal(&hit));
        Ray reflected = secondary_ray(&hit, r, dir, tr->offset);
        Color mirrored = tracer_trace(tr, reflected, RAY_REFLECTED, depth + 1, path);
        radiance = color_add(radiance, color_mul(km, mirrored));
    }
    return radiance;
}

/* excerpt: tracer-seams */
/* Finds the closest surface along r (t > 0) with the tracer's Surfaces, and tells it. */
bool tracer_hit(const Tracer *tr, Ray r, int depth, Hit *hit)
{
    if (!tr->surfaces.hit(tr->surfaces.data, r, 0, INFINITY, hit)) {
        explain_line(tr->explain, depth + 1, "hits nothing: the black background");
        return false;
    }
    world_explain_hit(tr->explain, depth + 1, hit);
    return true;
}

/* Tells whether anything lies on the shadow ray with 0 < t < tmax, counting it; when
 * something does, tells the ray and the first thing on it. */
bool tracer_blocked(const Tracer *tr, Ray shadow, double tmax, int depth, Path *path)
{
    path->stats->rays[RAY_SHADOW]++;
    if (!tr->surfaces.blocked(tr->surfaces.data, shadow, 0, tmax))
        return false;
    if (tr->explain != NULL) {
        Hit blocker;
        explain_ray(tr->explain, depth + 2, "shadow", shadow);
        if (tr->surfaces.hit(tr->surfaces.data, shadow, 0, tmax, &blocker))
            world_explain_hit(tr->explain, depth + 3, &blocker);
    }
    return true;
}

/* Finds the closest surface on a shadow ray with 0 < t < tmax, for a walk through glass
 * that has crossed so many surfaces already. The first stretch is the ray that
 * tracer_blocked counted and told; each later one, from a glass surface on, is a shadow
 * ray of its own: counted, and told with what it meets or that it reaches the light. */
bool tracer_shadow_hit(const Tracer *tr, Ray shadow, double tmax, int crossed, int depth, Hit *hit,
                       Path *path)
{
    bool found = tr->surfaces.hit(tr->surfaces.data, shadow, 0, tmax, hit);
    if (crossed == 0)
        return found;
    path->stats->rays[RAY_SHADOW]++;
    if (tr->explain != NULL) {
        char from[96], along[96];
        explain_line(tr->explain, depth + 2,
                     "shadow ray on through glass (crossing %d) from %s along %s", crossed,
                     explain_vec3(shadow.origin, from, sizeof from),
                     explain_vec3(shadow.dir, along, sizeof along));
        if (found)
            world_explain_hit(tr->explain, depth + 3, hit);
        else
            explain_line(tr->explain, depth + 3, "reaches the light");
    }
    return found;
}

/* Returns the radiance along a ray that a hit sends on (or the camera's, at depth 0),
 * counting it as kind: the tracer's radiance hook, told with its ray and its result. */
Color tracer_trace(const Tracer *tr, Ray r, RayKind kind, int depth, Path *path)
{
    path->stats->rays[kind]++;
    explain_ray(tr->explain, depth, kind == RAY_PRIMARY ? "camera" : render_ray_kind_name(kind), r);
    const TracerHooks *h = &tr->hooks;
    Color c = h->radiance(h->radiance_ctx, tr, r, depth, path);
    explain_color(tr->explain, depth + 1, "radiance", c);
    return c;
}

/* Prints, for --trace-pixel, which light k is, and whether it is behind the surface. */
static void explain_light(const Tracer *tr, const Hit *hit, int k, int depth)
{
    static const char *const kinds[] = {"point", "directional", "area"};
    const Light *light = &tr->scene->lights[k];
    char where[300];
    explain_line(tr->explain, depth + 1, "light %d, %s%s", k, kinds[light->kind],
                 explain_where(tr->explain, light->line, where, sizeof where));
    if (light->kind != LIGHT_AREA &&
        vec3_dot(shade_normal(hit), light_incident(light, hit->point, false).dir) <= 0)
        explain_line(tr->explain, depth + 2, "behind the surface");
}

/* Returns the light that light k sends back along r from hit: the tracer's light hook,
 * told with the light and what it adds. */
Color tracer_light(const Tracer *tr, const Hit *hit, Ray r, int k, int depth, Path *path)
{
    if (tr->explain != NULL)
        explain_light(tr, hit, k, depth);
    const Light *light = &tr->scene->lights[k];
    const TracerHooks *h = &tr->hooks;
    Color c = h->light(h->light_ctx, tr, hit, r, light, depth, path);
    explain_color(tr->explain, depth + 2, "adds", c);
    return c;
}

/* Returns the fraction of the light in that reaches hit's point: the tracer's through
 * hook, told with where the light comes from and, when some of it arrives, its
 * Blinn-Phong terms. */
Color tracer_through(const Tracer *tr, const Hit *hit, Ray r, const Incident *in, int depth,
                     Path *path)
{
    const Explain *e = tr->explain;
    if (e != NULL) {
        char l[96];
        explain_line(e, depth + 2, "towards it %s, arriving (%.6g, %.6g, %.6g)",
                     explain_vec3(in->dir, l, sizeof l), in->radiance.r, in->radiance.g,
                     in->radiance.b);
    }
    const TracerHooks *h = &tr->hooks;
    Color through = h->through(h->through_ctx, tr, hit, r, in, depth, path);
    if (e != NULL) {
        if (color_is_black(through)) {
            explain_line(e, depth + 2, "in shadow");
            return through;
        }
        if (through.r < 1 || through.g < 1 || through.b < 1)
            explain_color(e, depth + 2, "what gets through", through);
        const Material *m = shade_material(tr->scene, hit, tr->two_sided);
        BlinnPhong terms = shade_blinn_phong_terms(m, shade_normal(hit), vec3_neg(r.dir), in);
        explain_color(e, depth + 2, "diffuse", color_mul(through, terms.diffuse));
        explain_color(e, depth + 2, "specular", color_mul(through, terms.specular));
    }
    return through;
}
/* end excerpt: tracer-seams */

/* Tells --view what ray r meets first, how many lights reach the point: in front of the
 * surface and not in shadow (part 1.6's area lights as points at their centres), and how
 * many boxes and surfaces the search for it tested. */
void trace_probe(const Tracer *tr, Ray r, Probe *probe)
{
    Hit hit;
    probe->tests = tr->surfaces.tests(tr->surfaces.data, r);
    if (!tr->surfaces.hit(tr->surfaces.data, r, 0, INFINITY, &hit))
        return;
    const Scene *scene = tr->scene;
    Vec3 n = shade_normal(&hit);
    *probe = (Probe){.hit = true,
                     .t = hit.t,
                     .normal = n,
                     .surface = world_surface_id(scene, &hit),
                     .kd = shade_material(scene, &hit, tr->two_sided)->diffuse,
                     .tests = probe->tests};
    RayStats stats = {{0}};
    Path path = {.stats = &stats, .weight = 1};
    for (int k = 0; k < scene->light_count; k++) {
        /* An area light counts when the light hook lights it (part 1.6's does). */
        if (scene->lights[k].kind == LIGHT_AREA && !tr->hooks.light_areas)
            continue;
        Incident in = light_incident(&scene->lights[k], hit.point, false);
        probe->lights_visible +=
            vec3_dot(n, in.dir) > 0 && !direct_in_shadow(tr, &hit, r, &in, 0, &path);
    }
}

/* Estimates, for --trace-pixel, the lines the tree of rays camera rays prints: about 8
 * for each hit, 5 for each point or directional light, and for each area light 5 for
 * each of its area_rays samples (none before part 1.6, which samples them); mirrors and
 * glass add up to max_depth more hits a camera ray, in *most. */
void tracer_trace_lines(const Tracer *tr, double rays, double area_rays, double *fewest,
                        double *most)
{
    const Scene *scene = tr->scene;
    double per_hit = 8;
    for (int k = 0; k < scene->light_count; k++)
        per_hit += scene->lights[k].kind == LIGHT_AREA ? 2 + 5 * area_rays : 5;
    *fewest = rays * (2 + per_hit);
    bool bounces = scene_features(scene) & (FEATURE_MIRRORS | FEATURE_REFRACTION);
    *most = *fewest + (bounces ? rays * per_hit * tr->max_depth : 0);
}

/* Returns the radiance along the camera ray through the centre of pixel (i, j): the
 * pixel of part 1.3, and of every later part that traces with its Tracer. */
Color trace_camera_pixel(const Tracer *tr, const Camera *cam, int i, int j, RayStats *stats)
{
    Path path = {.stats = stats, .weight = 1};
    return tracer_trace(tr, camera_ray(cam, i + 0.5, j + 0.5), RAY_PRIMARY, 0, &path);
}

/* The pixel of part 1.3, and of the later parts that keep it, as a Program's pixel: its
 * context is a TraceView. */
Color trace_view_pixel(const void *ctx, int i, int j, RayStats *stats)
{
    const TraceView *view = ctx;
    return trace_camera_pixel(view->tracer, &view->camera, i, j, stats);
}

/* Tells --view what the camera ray through the centre of pixel (i, j) of the TraceView ctx
 * meets first (trace_probe). */
void trace_view_probe(const void *ctx, int i, int j, Probe *probe)
{
    const TraceView *view = ctx;
    trace_probe(view->tracer, camera_ray(&view->camera, i + 0.5, j + 0.5), probe);
}

/* Estimates the lines --trace-pixel prints for the TraceView ctx: one camera ray a pixel. */
void trace_view_lines(const void *ctx, int sample, double *fewest, double *most)
{
    (void)sample;
    tracer_trace_lines(((const TraceView *)ctx)->tracer, 1, 0, fewest, most);
}
