/* refract.c: part 1.5's tracing: mirrors as in part 1.3, and glass that reflects and refracts. */
#include "refract.h"

#include <math.h>
#include <stdio.h>

#include "direct.h"
#include "secondary.h"
#include "shade.h"
#include "transmit.h"

/* Reads --fresnel into *fresnel (Schlick's when it is not given); false, said on standard
 * error, when it names no model. */
static bool fresnel_option(const Options *opts, FresnelModel *fresnel)
{
    const char *name = cli_text(opts, "fresnel");
    *fresnel = FRESNEL_SCHLICK;
    if (name != NULL && !dielectric_fresnel_from_name(name, fresnel)) {
        fprintf(stderr, "raytra: --fresnel takes schlick or exact, got '%s'\n", name);
        return false;
    }
    return true;
}

/* Sets rf up for scene from the command line (the one place that reads part 1.5's
 * options). False (said) on a bad --fresnel. */
bool refract_init(Refractor *rf, const Scene *scene, const Options *opts)
{
    *rf = (Refractor){.min_weight = cli_number(opts, "min-weight")};
    if (!fresnel_option(opts, &rf->fresnel))
        return false;
    for (int k = 0; k < scene->material_count; k++)
        rf->has_glass |= refract_is_glass(&scene->materials[k]);
    return true;
}

/* Part 1.5's hooks, which it hands its tracer with its Refractor as their context: lights
 * as part 1.3 lights them (direct_light), shadow rays that pass through glass
 * (transmit_light). */
const TracerHooks refract_hooks = {.light = direct_light, .through = transmit_light};

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

/* Returns the largest of c's channels. */
static double color_max(Color c)
{
    return fmax(c.r, fmax(c.g, c.b));
}

/* Returns the radiance along the ray that leaves hit in direction dir, counted as kind,
 * or black when its share of the pixel, weight, is too small to see (--min-weight):
 * Hall and Greenberg's adaptive depth control. */
static Color follow(const Refractor *rf, const Tracer *tr, const Hit *hit, Ray r, Vec3 dir,
                    RayKind kind, int depth, double weight, Path *path)
{
    if (weight <= 0 || weight < rf->min_weight) {
        explain_line(tr->explain, depth + 1, "%s ray not followed: it would count %.3g",
                     render_ray_kind_name(kind), weight);
        return color(0, 0, 0);
    }
    /* secondary_ray starts it on the side it goes to: inside when it enters glass. */
    Ray next = secondary_ray(hit, r, dir, tr->offset);
    return refract_trace(rf, tr, next, kind, depth + 1, weight, path);
}

/* Returns the light that the glass surface at hit (of material m) sends back along r
 * through Fresnel reflection and refraction: R times the radiance along the reflected
 * ray plus (1 - R) times the radiance along the refracted ray. */
static Color glass_radiance(const Refractor *rf, const Tracer *tr, const Hit *hit,
                            const Material *m, Ray r, int depth, double weight, Path *path)
{
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
    explain_line(tr->explain, depth + 1, "glass of index %g, %s it: %s, R = %.6g", m->ior,
                 entering ? "entering" : "leaving",
                 refracts ? "refracted" : "total internal reflection", reflectance);
    Vec3 mirrored = secondary_reflect(r.dir, n);
    Color sum = color_scale(
        follow(rf, tr, hit, r, mirrored, RAY_REFLECTED, depth, weight * reflectance, path),
        reflectance);
    if (refracts) {
        Color seen =
            follow(rf, tr, hit, r, t, RAY_REFRACTED, depth, weight * (1 - reflectance), path);
        sum = color_add(sum, color_scale(seen, 1 - reflectance));
    }
    return sum;
}

/* Returns the radiance arriving along ray r: the light of the first surface it meets,
 * straight from the lights, plus k_m times the radiance along the mirror-reflected ray,
 * plus, for glass, the Fresnel-weighted radiance along the reflected and refracted rays
 * (times 1 - max(k_m) when the glass is a mirror too);
 * all of it dimmed by Beer's law when r travelled inside glass. Replaces part 1.3's
 * trace_radiance; depth counts the reflections and refractions before r, and weight is
 * r's share of its pixel. */
static Color refract_radiance(const Refractor *rf, const Tracer *tr, Ray r, int depth,
                              double weight, Path *path)
{
    Hit found;
    if (!tracer_hit(tr, r, depth, &found))
        return color(0, 0, 0);
    Hit hit = refract_glass_hit(tr->scene, &found);
    const Material *m = shade_material(tr->scene, &hit, tr->two_sided);
    /* A ray that meets glass from behind travelled inside it, all the way from its
     * origin: what it carries back is absorbed along those t units of distance. */
    Color absorbed = color(1, 1, 1);
    if (found.back_face && refract_is_glass(m))
        absorbed = dielectric_beer(m->attenuation, found.t);
    weight *= color_max(absorbed);

    Color radiance = direct_radiance(tr, &hit, r, depth, path);
    /* Mirror, reflected and refracted rays share one budget: at its end, a branch
     * adds nothing more. */
    if (depth < tr->max_depth) {
        /* An ideal mirror, as in part 1.3; its reflected ray may now meet glass. */
        if (!color_is_black(m->mirror)) {
            Vec3 dir = secondary_reflect(r.dir, shade_normal(&hit));
            Color mirrored = follow(rf, tr, &hit, r, dir, RAY_REFLECTED, depth,
                                    weight * color_max(m->mirror), path);
            radiance = color_add(radiance, color_mul(m->mirror, mirrored));
        }
        /* Glass under a mirror coating gets the light that the mirror leaves in its
         * strongest channel, 1 - max(k_m): with it the weights of r's children add up to
         * at most r's own, so --min-weight bounds the tree (docs/1.5-refraction.md). */
        double glass_share = 1 - color_max(m->mirror);
        if (refract_is_glass(m) && glass_share > 0) {
            Color glass = glass_radiance(rf, tr, &found, m, r, depth, weight * glass_share, path);
            radiance = color_add(radiance, color_scale(glass, glass_share));
        }
    }
    if (found.back_face && refract_is_glass(m))
        explain_color(tr->explain, depth + 1, "times a^t, absorbed inside", absorbed);
    return color_mul(radiance, absorbed);
}

/* Returns the radiance along a ray that a hit sends on (or the camera's, at depth 0),
 * counted as kind, whose share of its pixel is weight: refract_radiance, between the
 * seams that tell the ray and its result. Replaces part 1.3's tracer_trace. */
Color refract_trace(const Refractor *rf, const Tracer *tr, Ray r, RayKind kind, int depth,
                    double weight, Path *path)
{
    tracer_cast(tr, r, kind, depth, path);
    return tracer_arrived(tr, depth, refract_radiance(rf, tr, r, depth, weight, path));
}
