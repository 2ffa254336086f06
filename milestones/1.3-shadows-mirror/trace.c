/* trace.c: the function that returns the radiance along a ray, and calls itself for mirrors. */
#include "trace.h"

#include "direct.h"
#include "secondary.h"
#include "shade.h"

/* excerpt: trace-radiance */
/* Returns the radiance arriving along ray r: the light of the first surface it meets,
 * straight from the lights, plus k_m times the radiance along the mirror-reflected ray.
 * depth counts the reflections that led to r; primary rays have depth 0. */
Color trace_radiance(const Tracer *tr, Ray r, int depth, RayStats *stats)
{
    Hit hit;
    if (!tr->surfaces.hit(tr->surfaces.data, r, 0, INFINITY, &hit))
        return color(0, 0, 0); /* the background */
    if (shade_shows_back_face(&hit) && !tr->two_sided)
        return SHADE_BACK_FACE_COLOR;

    Color radiance = direct_radiance(tr, &hit, r, stats);

    /* An ideal mirror sends back k_m of what arrives from the mirror direction, which is
     * what a ray traced in that direction finds: the same question, one bounce later. */
    Color km = tr->scene->materials[hit.material].mirror;
    if (!color_is_black(km) && depth < tr->max_depth) {
        Vec3 dir = secondary_reflect(r.dir, shade_normal(&hit));
        Ray reflected = secondary_ray(&hit, r, dir, tr->offset);
        stats->rays[RAY_REFLECTED]++;
        Color mirrored = trace_radiance(tr, reflected, depth + 1, stats);
        radiance = color_add(radiance, color_mul(km, mirrored));
    }
    return radiance;
}
/* end excerpt: trace-radiance */
