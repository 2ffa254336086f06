/* direct.c: ambient light plus Blinn-Phong from every light that a shadow ray finds unblocked. */
#include "direct.h"

#include "secondary.h"
#include "shade.h"

/* excerpt: direct-in-shadow */
/* Tells whether something lies between hit's point and the light in: a shadow ray from
 * the point towards the light, which must not reach as far as the light itself. */
bool direct_in_shadow(const Tracer *tr, const Hit *hit, Ray r, const Incident *in, Path *path)
{
    Ray shadow = secondary_ray(hit, r, in->dir, tr->offset);
    path->stats->rays[RAY_SHADOW]++;
    /* Only what lies before the light blocks it, measured from the shadow ray's own
     * origin, a hair off the point. A directional light is infinitely far away. */
    double tmax = in->distance - vec3_dot(vec3_sub(shadow.origin, hit->point), in->dir);
    return tr->surfaces.blocked(tr->surfaces.data, shadow, 0, tmax);
}
/* end excerpt: direct-in-shadow */

/* excerpt: direct-radiance */
/* Returns the light that hit's surface reflects back along ray r straight from the
 * lights: k_d (.) ambient, plus Blinn-Phong for each light that is not in shadow.
 * Replaces part 1.2's shade_direct_radiance; depth counts the reflections before r. */
Color direct_radiance(const Tracer *tr, const Hit *hit, Ray r, int depth, Path *path)
{
    const Scene *scene = tr->scene;
    const Material *m = shade_material(scene, hit, tr->two_sided);
    Vec3 n = shade_normal(hit);
    Vec3 v = vec3_neg(r.dir);
    /* The ambient light stands for the light bounced around by everything else, from
     * no particular direction (slide 21). The lecture convention adds it at every hit;
     * the Fall 2016 term's renderers only where camera rays hit (docs/1.3). */
    Color sum = color(0, 0, 0);
    if (depth == 0 || scene->convention != CONVENTION_FALL2016)
        sum = color_mul(m->diffuse, scene->ambient);
    for (int k = 0; k < scene->light_count; k++) {
        Incident in = light_incident(&scene->lights[k], hit->point, scene_light_falls_off(scene));
        /* No shadow ray for a light behind the surface: it adds nothing anyway. */
        if (vec3_dot(n, in.dir) <= 0 || direct_in_shadow(tr, hit, r, &in, path))
            continue;
        sum = color_add(sum, shade_blinn_phong(m, n, v, &in));
    }
    return sum;
}
/* end excerpt: direct-radiance */
