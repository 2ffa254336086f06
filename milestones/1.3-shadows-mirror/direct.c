/* direct.c: ambient light plus Blinn-Phong from every light that a shadow ray finds unblocked. */
#include "direct.h"

#include "secondary.h"
#include "shade.h"

/* starter: todo */
/* Returns the shadow ray from hit's point towards the light in, and in *tmax how far
 * it may go: only what lies before the light blocks it, measured from the ray's own
 * origin, a hair off the point. A directional light is infinitely far away. */
Ray direct_shadow_ray(const Tracer *tr, const Hit *hit, Ray r, const Incident *in, double *tmax)
{
    Ray shadow = secondary_ray(hit, r, in->dir, tr->offset);
    *tmax = in->distance - vec3_dot(vec3_sub(shadow.origin, hit->point), in->dir);
    return shadow;
}

/* Tells whether something lies between hit's point and the light in: a shadow ray from
 * the point towards the light, which must not reach as far as the light itself. */
bool direct_in_shadow(const Tracer *tr, const Hit *hit, Ray r, const Incident *in, int depth,
                      Path *path)
{
    double tmax = 0;
    Ray shadow = direct_shadow_ray(tr, hit, r, in, &tmax);
    return tracer_blocked(tr, shadow, tmax, depth, path);
}

/* Part 1.3's through hook: all of the light, or none of it when in shadow. */
Color direct_through(const void *ctx, const Tracer *tr, const Hit *hit, Ray r, const Incident *in,
                     int depth, Path *path)
{
    (void)ctx;
    return direct_in_shadow(tr, hit, r, in, depth, path) ? color(0, 0, 0) : color(1, 1, 1);
}

/* starter: todo */
/* Returns the light that hit's surface reflects back along ray r from the beam in:
 * Blinn-Phong, times the fraction of the beam that reaches the point
 * (tracer_through: none when a shadow ray finds something in the way). */
Color direct_incident(const Tracer *tr, const Hit *hit, Ray r, const Incident *in, int depth,
                      Path *path)
{
    Vec3 n = shade_normal(hit);
    /* No shadow ray for a light behind the surface, or a dark one: it adds nothing anyway. */
    if (vec3_dot(n, in->dir) <= 0 || color_is_black(in->radiance))
        return color(0, 0, 0);
    Color through = tracer_through(tr, hit, r, in, depth, path);
    if (color_is_black(through))
        return through;
    const Material *m = shade_material(tr->scene, hit, tr->two_sided);
    return color_mul(through, shade_blinn_phong(m, n, vec3_neg(r.dir), in));
}

/* Part 1.3's light hook: the light of one point or directional light, by direct_incident.
 * An area light waits for part 1.6, which samples its square: until then it adds nothing,
 * and the trace says so. */
Color direct_light(const void *ctx, const Tracer *tr, const Hit *hit, Ray r, const Light *light,
                   int depth, Path *path)
{
    (void)ctx;
    if (light->kind == LIGHT_AREA) {
        explain_line(tr->explain, depth + 2,
                     "an area light: part 1.6 samples it; until then it adds nothing");
        return color(0, 0, 0);
    }
    Incident in = light_incident(light, hit->point, scene_light_falls_off(tr->scene));
    return direct_incident(tr, hit, r, &in, depth, path);
}

/* Part 1.3's hooks, which parts 1.3 and 1.4 hand their tracers: point and directional
 * lights by Blinn-Phong (direct_light), shadows all or nothing (direct_through). */
const TracerHooks direct_hooks = {.light = direct_light, .through = direct_through};

/* Returns k_d (.) ambient, slide 21 ("+ shadows + ambient"): at every hit by the lecture
 * convention, where camera rays hit only by fall2016's (docs/1.3-shadows-mirror.md). */
Color direct_ambient(const Tracer *tr, const Material *m, int depth)
{
    const Scene *scene = tr->scene;
    Color ambient = color(0, 0, 0);
    if (depth == 0 || scene->convention != CONVENTION_FALL2016)
        ambient = color_mul(m->diffuse, scene->ambient);
    shade_explain_material(tr->explain, depth + 1, m);
    explain_color(tr->explain, depth + 1, "ambient, kd (.) ambient light", ambient);
    return ambient;
}

/* starter: todo */
/* Returns the light that hit's surface reflects back along ray r straight from the
 * lights: k_d (.) ambient, plus what each light sends (tracer_light: Blinn-Phong, unless
 * in shadow). Replaces part 1.2's shade_direct_radiance; depth counts the reflections
 * before r. */
Color direct_radiance(const Tracer *tr, const Hit *hit, Ray r, int depth, Path *path)
{
    const Material *m = shade_material(tr->scene, hit, tr->two_sided);
    Color sum = direct_ambient(tr, m, depth);
    for (int k = 0; k < tr->scene->light_count; k++)
        sum = color_add(sum, tracer_light(tr, hit, r, k, depth, path));
    return sum;
}
