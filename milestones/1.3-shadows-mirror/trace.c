/* trace.c: the function that returns the radiance along a ray, and calls itself for mirrors. */
#include "trace.h"

#include "direct.h"
#include "secondary.h"
#include "shade.h"

/* Returns the tracer of scene, finding hits with surfaces, set up by the command line. */
Tracer tracer_make(const Scene *scene, Surfaces surfaces, const Options *opts)
{
    return (Tracer){.scene = scene,
                    .surfaces = surfaces,
                    .max_depth = opts->max_depth,
                    .two_sided = opts->two_sided,
                    .offset = opts->ray_offset,
                    .direct = direct_radiance};
}

/* excerpt: trace-radiance */
/* Returns the radiance arriving along ray r: the light of the first surface it meets,
 * straight from the lights, plus k_m times the radiance along the mirror-reflected ray.
 * depth counts the reflections that led to r; primary rays have depth 0. */
Color trace_radiance(const Tracer *tr, Ray r, int depth, Path *path)
{
    Hit hit;
    if (!tr->surfaces.hit(tr->surfaces.data, r, 0, INFINITY, &hit))
        return color(0, 0, 0); /* the background */
    Color radiance = tr->direct(tr, &hit, r, depth, path);

    /* An ideal mirror sends back k_m of what arrives from the mirror direction, which is
     * what a ray traced in that direction finds: the same question, one bounce later. */
    Color km = shade_material(tr->scene, &hit, tr->two_sided)->mirror;
    if (!color_is_black(km) && depth < tr->max_depth) {
        Vec3 dir = secondary_reflect(r.dir, shade_normal(&hit));
        Ray reflected = secondary_ray(&hit, r, dir, tr->offset);
        path->stats->rays[RAY_REFLECTED]++;
        Color mirrored = trace_radiance(tr, reflected, depth + 1, path);
        radiance = color_add(radiance, color_mul(km, mirrored));
    }
    return radiance;
}
/* end excerpt: trace-radiance */
