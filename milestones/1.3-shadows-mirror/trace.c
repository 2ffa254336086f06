/* trace.c: the radiance along a ray, part 1.3's pixel, and what --view sees of it. */
#include "trace.h"

#include "direct.h"
#include "secondary.h"
#include "shade.h"
#include "world.h"

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

/* Returns the radiance along a ray that a hit sends on (or the camera's, at depth 0),
 * counted as kind: trace_radiance, between the seams that tell the ray and its result. */
Color tracer_trace(const Tracer *tr, Ray r, RayKind kind, int depth, Path *path)
{
    tracer_cast(tr, r, kind, depth, path);
    return tracer_arrived(tr, depth, trace_radiance(tr, r, depth, path));
}

/* Tells --view what ray r meets first, how many lights of the kinds in features (the
 * FEATURE_ bits of what the part renders) reach the point: in front of the surface and
 * not in shadow (area lights as points at their centres), and how many boxes and
 * surfaces the search for it tested. */
void trace_probe(const Tracer *tr, Ray r, unsigned features, Probe *probe)
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
    Path path = {.stats = &stats};
    for (int k = 0; k < scene->light_count; k++) {
        if (!(features & scene_light_feature(scene->lights[k].kind)))
            continue;
        Incident in = light_incident(&scene->lights[k], hit.point, false);
        probe->lights_visible +=
            vec3_dot(n, in.dir) > 0 && !direct_in_shadow(tr, &hit, r, &in, 0, &path);
    }
}

/* Returns the radiance along the camera ray through the centre of pixel (i, j) of the
 * TraceView ctx: the pixel of parts 1.3 and 1.4, as a Program's pixel. */
Color trace_view_pixel(const void *ctx, int i, int j, RayStats *stats)
{
    const TraceView *view = ctx;
    Path path = {.stats = stats};
    return tracer_trace(view->tracer, camera_ray(&view->camera, i + 0.5, j + 0.5), RAY_PRIMARY, 0,
                        &path);
}

/* Tells --view what the camera ray through the centre of pixel (i, j) of the TraceView ctx
 * meets first (trace_probe). */
void trace_view_probe(const void *ctx, int i, int j, Probe *probe)
{
    const TraceView *view = ctx;
    trace_probe(view->tracer, camera_ray(&view->camera, i + 0.5, j + 0.5), TRACER_FEATURES, probe);
}

/* Estimates the lines --trace-pixel prints for the TraceView ctx: one camera ray a pixel. */
void trace_view_lines(const void *ctx, int sample, double *fewest, double *most)
{
    (void)sample;
    tracer_trace_lines(((const TraceView *)ctx)->tracer, 1, 0, fewest, most);
}
