/* refract.c: part 1.5's radiance function: mirrors as in part 1.3, and glass that reflects and refracts. */
#include "refract.h"

#include "secondary.h"
#include "shade.h"
#include "transmit.h"

/* Returns the tracer of scene with glass, finding hits with surfaces, set up by the
 * command line; its direct light lets shadow rays through glass (transmit.c). */
Refractor refract_make(const Scene *scene, Surfaces surfaces, FresnelModel fresnel,
                       const Options *opts)
{
    Refractor rf = {.tracer = tracer_make(scene, surfaces, opts), .fresnel = fresnel};
    rf.tracer.direct = transmit_direct_radiance;
    for (int k = 0; k < scene->material_count; k++)
        rf.has_glass |= refract_is_glass(&scene->materials[k]);
    return rf;
}

/* excerpt: refract-glass-hit */
/* Returns hit as the shading sees it. The back of a glass triangle or plane is the inside
 * of a solid, not a wrongly wound face: it keeps its own material, not part 1.2's yellow,
 * and, like the inside of a sphere, is shaded with the normal turned to face the ray. */
Hit refract_glass_hit(const Scene *scene, const Hit *hit)
{
    Hit seen = *hit;
    if (hit->back_face && refract_is_glass(&scene->materials[hit->material])) {
        seen.normal = vec3_neg(hit->normal);
        seen.back_face = false;
    }
    return seen;
}
/* end excerpt: refract-glass-hit */

/* excerpt: refract-glass */
/* Returns the light that the glass surface at hit (of material m) sends back along r
 * through Fresnel reflection and refraction: R times the radiance along the reflected
 * ray plus (1 - R) times the radiance along the refracted ray. */
static Color glass_radiance(const Refractor *rf, const Hit *hit, const Material *m, Ray r,
                            int depth, Path *path)
{
    const Tracer *tr = &rf->tracer;
    /* Which side is which: a ray that meets the front of the surface enters the glass
     * from the air (n = 1); one that meets the back leaves it. */
    bool entering = !hit->back_face;
    Vec3 n = shade_normal(hit); /* facing the ray */
    double eta = entering ? 1 / m->ior : m->ior;
    Vec3 t;
    double reflectance = 1; /* total internal reflection unless a refracted ray exists */
    bool refracts = dielectric_refract(r.dir, n, eta, &t);
    if (refracts) {
        /* Fresnel's R is the same both ways: take the cosine on the air side, the
         * incident ray's when entering, the refracted ray's when leaving. */
        double cos_air = entering ? -vec3_dot(r.dir, n) : -vec3_dot(t, n);
        reflectance = dielectric_reflectance(rf->fresnel, m->ior, cos_air);
    }
    Color sum = color(0, 0, 0);
    if (reflectance > 0) {
        Ray reflected = secondary_ray(hit, r, secondary_reflect(r.dir, n), tr->offset);
        path->stats->rays[RAY_REFLECTED]++;
        Color seen = refract_radiance(rf, reflected, depth + 1, path);
        sum = color_add(sum, color_scale(seen, reflectance));
    }
    if (refracts && reflectance < 1) {
        /* secondary_ray starts it on the side it goes to: inside when entering. */
        Ray refracted = secondary_ray(hit, r, t, tr->offset);
        path->stats->rays[RAY_REFRACTED]++;
        Color seen = refract_radiance(rf, refracted, depth + 1, path);
        sum = color_add(sum, color_scale(seen, 1 - reflectance));
    }
    return sum;
}
/* end excerpt: refract-glass */

/* excerpt: refract-radiance */
/* Returns the radiance arriving along ray r: the light of the first surface it meets,
 * straight from the lights, plus k_m times the radiance along the mirror-reflected ray,
 * plus, for glass, the Fresnel-weighted radiance along the reflected and refracted rays;
 * all of it dimmed by Beer's law when r travelled inside glass. Replaces part 1.3's
 * trace_radiance; depth counts the reflections and refractions before r. */
Color refract_radiance(const Refractor *rf, Ray r, int depth, Path *path)
{
    const Tracer *tr = &rf->tracer;
    Hit found;
    if (!tr->surfaces.hit(tr->surfaces.data, r, 0, INFINITY, &found))
        return color(0, 0, 0); /* the background */
    Hit hit = refract_glass_hit(tr->scene, &found);
    Color radiance = tr->direct(tr, &hit, r, depth, path);
    const Material *m = shade_material(tr->scene, &hit, tr->two_sided);
    /* Mirror, reflected and refracted rays share one budget: at its end, a branch
     * adds nothing more. */
    if (depth < tr->max_depth) {
        /* An ideal mirror, as in part 1.3; its reflected ray may now meet glass. */
        if (!color_is_black(m->mirror)) {
            Vec3 dir = secondary_reflect(r.dir, shade_normal(&hit));
            Ray reflected = secondary_ray(&hit, r, dir, tr->offset);
            path->stats->rays[RAY_REFLECTED]++;
            Color mirrored = refract_radiance(rf, reflected, depth + 1, path);
            radiance = color_add(radiance, color_mul(m->mirror, mirrored));
        }
        if (refract_is_glass(m))
            radiance = color_add(radiance, glass_radiance(rf, &found, m, r, depth, path));
    }
    /* A ray that meets glass from behind travelled inside it, all the way from its
     * origin: what it carries back was absorbed along those t units of distance. */
    if (found.back_face && refract_is_glass(m))
        radiance = color_mul(radiance, dielectric_beer(m->attenuation, found.t));
    return radiance;
}
/* end excerpt: refract-radiance */
