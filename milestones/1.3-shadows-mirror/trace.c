/* trace.c: the function that returns the radiance along a ray, and calls itself for mirrors. */
#include "trace.h"

#include "direct.h"
#include "secondary.h"
#include "shade.h"
#include "world.h"

/* Returns the tracer of scene, finding hits with surfaces, set up by the command line. */
Tracer tracer_make(const Scene *scene, Surfaces surfaces, const Options *opts)
{
    return (Tracer){.scene = scene,
                    .surfaces = surfaces,
                    .max_depth = opts->max_depth,
                    .two_sided = opts->two_sided,
                    .offset = opts->ray_offset,
                    .direct = direct_radiance,
                    .explain = opts->explain};
}

/* starter: todo */
/* excerpt: trace-radiance */
/* Returns the radiance arriving along ray r: the light of the first surface it meets,
 * straight from the lights, plus k_m times the radiance along the mirror-reflected ray.
 * depth counts the reflections that led to r; primary rays have depth 0. */
Color trace_radiance(const Tracer *tr, Ray r, int depth, Path *path)
{
    Hit hit;
    if (!tr->surfaces.hit(tr->surfaces.data, r, 0, INFINITY, &hit)) {
        explain_line(tr->explain, depth + 1, "hits nothing: the black background");
        return color(0, 0, 0);
    }
    world_explain_hit(tr->explain, depth + 1, &hit);
    Color radiance = tr->direct(tr, &hit, r, depth, path);

    /* An ideal mirror sends back k_m of what arrives from the mirror direction, which is
     * what a ray traced in that direction finds: the same question, one bounce later. */
    Color km = shade_material(tr->scene, &hit, tr->two_sided)->mirror;
    if (!color_is_black(km) && depth < tr->max_depth) {
        Vec3 dir = secondary_reflect(r.dir, shade_normal(&hit));
        Ray reflected = secondary_ray(&hit, r, dir, tr->offset);
        path->stats->rays[RAY_REFLECTED]++;
        explain_ray(tr->explain, depth + 1, "mirror", reflected);
        Color mirrored = trace_radiance(tr, reflected, depth + 1, path);
        explain_color(tr->explain, depth + 1, "times km", km);
        radiance = color_add(radiance, color_mul(km, mirrored));
    }
    explain_color(tr->explain, depth + 1, "radiance", radiance);
    return radiance;
}
/* end excerpt: trace-radiance */

/* Tells --view what ray r meets first, and how many lights reach the point: in front of
 * the surface and not in shadow. */
void trace_probe(const Tracer *tr, Ray r, Probe *probe)
{
    Hit hit;
    if (!tr->surfaces.hit(tr->surfaces.data, r, 0, INFINITY, &hit))
        return;
    const Scene *scene = tr->scene;
    Vec3 n = shade_normal(&hit);
    *probe = (Probe){.hit = true,
                     .t = hit.t,
                     .normal = n,
                     .surface = world_surface_id(scene, &hit),
                     .kd = shade_material(scene, &hit, tr->two_sided)->diffuse};
    RayStats stats = {{0}};
    Path path = {.stats = &stats};
    for (int k = 0; k < scene->light_count; k++) {
        Incident in = light_incident(&scene->lights[k], hit.point, false);
        probe->lights_visible +=
            vec3_dot(n, in.dir) > 0 && !direct_in_shadow(tr, &hit, r, &in, &path);
    }
}

/* excerpt: trace-pixel */
/* Returns the radiance along the camera ray through the centre of pixel (i, j): the
 * pixel of part 1.3, and of every later part that traces with its Tracer. */
Color trace_camera_pixel(const Tracer *tr, const Camera *cam, int i, int j, RayStats *stats)
{
    Ray r = camera_ray(cam, i + 0.5, j + 0.5);
    stats->rays[RAY_PRIMARY]++;
    explain_ray(tr->explain, 0, "camera", r);
    Path path = {.stats = stats};
    return trace_radiance(tr, r, 0, &path);
}
/* end excerpt: trace-pixel */
