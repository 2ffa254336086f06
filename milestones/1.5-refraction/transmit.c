/* transmit.c: shadow rays that pass through glass, dimmed by Fresnel and Beer but not bent. */
#include "transmit.h"

#include "direct.h"
#include "secondary.h"
#include "shade.h"

/* starter: todo */
/* excerpt: transmit-light */
/* Returns the fraction of the light in that reaches hit's point, per channel: 1 when
 * nothing lies between them, 0 when something opaque does, and when only glass does,
 * the product over the glass surfaces crossed of (1 - R), R taken at the shadow ray's
 * angle as if on the air side, and over the stretches inside glass of Beer's a^s.
 * The shadow ray is not bent: light that glass focuses or deflects onto the point
 * (caustics) is beyond a ray tracer that follows rays from the eye. */
Color transmit_light(const Refractor *rf, const Hit *hit, Ray r, const Incident *in, Path *path)
{
    const Tracer *tr = &rf->tracer;
    Ray shadow = secondary_ray(hit, r, in->dir, tr->offset);
    path->stats->rays[RAY_SHADOW]++;
    /* As in part 1.3: only what lies before the light counts, from the shadow ray's origin. */
    double tmax = in->distance - vec3_dot(vec3_sub(shadow.origin, hit->point), in->dir);
    if (!tr->surfaces.blocked(tr->surfaces.data, shadow, 0, tmax))
        return color(1, 1, 1);
    if (!rf->has_glass)
        return color(0, 0, 0);
    /* Something is in the way: walk along the ray from surface to surface. */
    Color through = color(1, 1, 1);
    for (int crossed = 0; crossed < TRANSMIT_MAX_CROSSINGS; crossed++) {
        Hit at;
        if (!tr->surfaces.hit(tr->surfaces.data, shadow, 0, tmax, &at))
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
        path->stats->rays[RAY_SHADOW]++;
    }
    return color(0, 0, 0);
}
/* end excerpt: transmit-light */

/* excerpt: transmit-direct-radiance */
/* Returns the light that hit's surface reflects back along ray r straight from the
 * lights: k_d (.) ambient, plus Blinn-Phong for each light, times the fraction of it
 * that gets through (transmit_light). Replaces part 1.3's direct_radiance, whose
 * shadow rays stop at glass; tr is the tracer of a Refractor. */
Color transmit_direct_radiance(const Tracer *tr, const Hit *hit, Ray r, int depth, Path *path)
{
    const Scene *scene = tr->scene;
    const Material *m = shade_material(scene, hit, tr->two_sided);
    shade_explain_material(tr->explain, depth + 1, m);
    Vec3 n = shade_normal(hit);
    Vec3 v = vec3_neg(r.dir);
    Color sum = direct_ambient(tr, m, depth); /* as in part 1.3 */
    for (int k = 0; k < scene->light_count; k++) {
        Incident in = light_incident(&scene->lights[k], hit->point, scene_light_falls_off(scene));
        if (vec3_dot(n, in.dir) <= 0) { /* it adds nothing, and needs no shadow ray */
            explain_line(tr->explain, depth + 1, "light %d: behind the surface", k);
            continue;
        }
        Color through = transmit_light(refractor_of(tr), hit, r, &in, path);
        if (color_is_black(through)) {
            explain_line(tr->explain, depth + 1, "light %d: in shadow", k);
            continue;
        }
        BlinnPhong terms = shade_blinn_phong_terms(m, n, v, &in);
        shade_explain_light(tr->explain, depth + 1, k, &in, terms);
        if (through.r < 1 || through.g < 1 || through.b < 1)
            explain_color(tr->explain, depth + 2, "times what gets through glass", through);
        sum = color_add(sum, color_mul(through, color_add(terms.diffuse, terms.specular)));
    }
    explain_color(tr->explain, depth + 1, "direct light", sum);
    return sum;
}
/* end excerpt: transmit-direct-radiance */
