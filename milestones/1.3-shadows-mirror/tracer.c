/* tracer.c: the seams through which every ray is traced, every hook called, and each step told. */
#include "tracer.h"

#include "shade.h"
#include "world.h"

/* Returns the tracer of scene, finding hits with surfaces, set up by the command line,
 * with the hooks of the part that makes it, handed ctx. */
Tracer tracer_make(const Scene *scene, Surfaces surfaces, const Options *opts,
                   const TracerHooks *hooks, const void *ctx)
{
    return (Tracer){.scene = scene,
                    .surfaces = surfaces,
                    .max_depth = cli_int(opts, "max-depth"),
                    .two_sided = cli_flag(opts, "two-sided"),
                    .offset = cli_number(opts, "ray-offset"),
                    .hooks = hooks,
                    .ctx = ctx,
                    .explain = opts->explain};
}

/* Returns a tracer that traces as below does (the scene, the geometry, the settings),
 * with the hooks of a part above it, handed ctx: part 1.6 makes one for each pixel
 * sample, whose own random numbers its hooks draw. */
Tracer tracer_extend(const Tracer *below, const TracerHooks *hooks, const void *ctx)
{
    Tracer tr = *below;
    tr.hooks = hooks;
    tr.ctx = ctx;
    return tr;
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

/* Counts a ray that a hit sends on (or the camera's, at depth 0) as kind, and tells it:
 * the first half of following a ray, whose radiance tracer_arrived tells. */
void tracer_cast(const Tracer *tr, Ray r, RayKind kind, int depth, Path *path)
{
    path->stats->rays[kind]++;
    explain_ray(tr->explain, depth, kind == RAY_PRIMARY ? "camera" : render_ray_kind_name(kind), r);
}

/* Returns the radiance that arrived along a ray cast at depth, and tells it. */
Color tracer_arrived(const Tracer *tr, int depth, Color radiance)
{
    explain_color(tr->explain, depth + 1, "radiance", radiance);
    return radiance;
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
    Color c = tr->hooks->light(tr->ctx, tr, hit, r, &tr->scene->lights[k], depth, path);
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
    Color through = tr->hooks->through(tr->ctx, tr, hit, r, in, depth, path);
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
