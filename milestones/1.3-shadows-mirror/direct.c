/* direct.c: ambient light plus Blinn-Phong from every light that a shadow ray finds unblocked. */
#include "direct.h"

#include "secondary.h"
#include "shade.h"
#include "world.h"

/* starter: todo */
/* excerpt: direct-in-shadow */
/* Returns the shadow ray from hit's point towards the light in, and in *tmax how far
 * it may go: only what lies before the light blocks it, measured from the ray's own
 * origin, a hair off the point. A directional light is infinitely far away. */
static Ray shadow_ray(const Tracer *tr, const Hit *hit, Ray r, const Incident *in, double *tmax)
{
    Ray shadow = secondary_ray(hit, r, in->dir, tr->offset);
    *tmax = in->distance - vec3_dot(vec3_sub(shadow.origin, hit->point), in->dir);
    return shadow;
}

/* Tells whether something lies between hit's point and the light in: a shadow ray from
 * the point towards the light, which must not reach as far as the light itself. */
bool direct_in_shadow(const Tracer *tr, const Hit *hit, Ray r, const Incident *in, Path *path)
{
    double tmax = 0;
    Ray shadow = shadow_ray(tr, hit, r, in, &tmax);
    path->stats->rays[RAY_SHADOW]++;
    return tr->surfaces.blocked(tr->surfaces.data, shadow, 0, tmax);
}
/* end excerpt: direct-in-shadow */

/* Prints, for --trace-pixel, the shadow ray towards light k and what blocks it. */
void direct_explain_blocked(const Tracer *tr, int depth, int k, const Hit *hit, Ray r,
                            const Incident *in)
{
    if (tr->explain == NULL)
        return;
    double tmax = 0;
    Ray shadow = shadow_ray(tr, hit, r, in, &tmax);
    explain_line(tr->explain, depth, "light %d: in shadow", k);
    explain_ray(tr->explain, depth + 1, "shadow", shadow);
    Hit blocker;
    if (tr->surfaces.hit(tr->surfaces.data, shadow, 0, tmax, &blocker))
        world_explain_hit(tr->explain, depth + 2, &blocker);
}

/* excerpt: direct-ambient */
/* Returns k_d (.) ambient, slide 21 ("+ shadows + ambient"): at every hit by the lecture
 * convention, where camera rays hit only by fall2016's (docs/1.3-shadows-mirror.md). */
Color direct_ambient(const Tracer *tr, const Material *m, int depth)
{
    const Scene *scene = tr->scene;
    Color ambient = color(0, 0, 0);
    if (depth == 0 || scene->convention != CONVENTION_FALL2016)
        ambient = color_mul(m->diffuse, scene->ambient);
    explain_color(tr->explain, depth + 1, "ambient, kd (.) ambient light", ambient);
    return ambient;
}
/* end excerpt: direct-ambient */

/* starter: todo */
/* excerpt: direct-radiance */
/* Returns the light that hit's surface reflects back along ray r straight from the
 * lights: k_d (.) ambient, plus Blinn-Phong for each light that is not in shadow.
 * Replaces part 1.2's shade_direct_radiance; depth counts the reflections before r. */
Color direct_radiance(const Tracer *tr, const Hit *hit, Ray r, int depth, Path *path)
{
    const Scene *scene = tr->scene;
    const Material *m = shade_material(scene, hit, tr->two_sided);
    shade_explain_material(tr->explain, depth + 1, m);
    Vec3 n = shade_normal(hit);
    Vec3 v = vec3_neg(r.dir);
    Color sum = direct_ambient(tr, m, depth);
    for (int k = 0; k < scene->light_count; k++) {
        Incident in = light_incident(&scene->lights[k], hit->point, scene_light_falls_off(scene));
        /* No shadow ray for a light behind the surface: it adds nothing anyway. */
        if (vec3_dot(n, in.dir) <= 0) {
            explain_line(tr->explain, depth + 1, "light %d: behind the surface", k);
            continue;
        }
        if (direct_in_shadow(tr, hit, r, &in, path)) {
            direct_explain_blocked(tr, depth + 1, k, hit, r, &in);
            continue;
        }
        BlinnPhong terms = shade_blinn_phong_terms(m, n, v, &in);
        shade_explain_light(tr->explain, depth + 1, k, &in, terms);
        sum = color_add(sum, color_add(terms.diffuse, terms.specular));
    }
    explain_color(tr->explain, depth + 1, "direct light", sum);
    return sum;
}
/* end excerpt: direct-radiance */
