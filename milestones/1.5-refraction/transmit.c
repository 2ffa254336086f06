/* transmit.c: shadow rays that pass through glass, dimmed by Fresnel and Beer but not bent. */
#include "transmit.h"

#include "direct.h"
#include "secondary.h"

/* starter: todo */
/* Returns the fraction of the light in that reaches hit's point, per channel: 1 when
 * nothing lies between them, 0 when something opaque does, and when only glass does,
 * the product over the glass surfaces crossed of (1 - R), R taken at the shadow ray's
 * angle as if on the air side, and over the stretches inside glass of Beer's a^s.
 * The shadow ray is not bent: light that glass focuses or deflects onto the point
 * (caustics) is beyond a ray tracer that follows rays from the eye. Part 1.5's through
 * hook, in place of part 1.3's all or nothing; ctx is the Refractor. */
Color transmit_light(const void *ctx, const Tracer *tr, const Hit *hit, Ray r, const Incident *in,
                     int depth, Path *path)
{
    const Refractor *rf = ctx;
    /* Part 1.3's shadow ray, which only what lies before the light blocks. */
    double tmax = 0;
    Ray shadow = direct_shadow_ray(tr, hit, r, in, &tmax);
    if (!tracer_blocked(tr, shadow, tmax, depth, path))
        return color(1, 1, 1);
    if (!rf->has_glass)
        return color(0, 0, 0);
    /* Something is in the way: walk along the ray from surface to surface. */
    Color through = color(1, 1, 1);
    for (int crossed = 0; crossed < TRANSMIT_MAX_CROSSINGS; crossed++) {
        Hit at;
        if (!tracer_shadow_hit(tr, shadow, tmax, crossed, depth, &at, path))
            return through; /* the rest of the way to the light is clear */
        const Material *m = &tr->scene->materials[at.material];
        if (!refract_is_glass(m))
            return color(0, 0, 0);
        double cos_air = fabs(vec3_dot(shadow.dir, at.normal));
        through = color_scale(through, 1 - dielectric_reflectance(rf->fresnel, m->ior, cos_air));
        /* Leaving glass from behind: the stretch since the ray's origin was inside it. */
        if (at.back_face)
            through = color_mul(through, dielectric_beer(m->attenuation, at.t));
        Ray next = secondary_ray(&at, shadow, shadow.dir, tr->offset);
        tmax -= vec3_dot(vec3_sub(next.origin, shadow.origin), shadow.dir);
        shadow = next;
    }
    return color(0, 0, 0);
}
