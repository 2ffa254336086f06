/* montecarlo.c: the pixel as the mean of P x P jittered rays, area lights as S x S shadow rays. */
#include "montecarlo.h"

#include <stdio.h>
#include <stdlib.h>

#include "area.h"
#include "shade.h"

/* Sets up mc to render scene: the camera, the tracer with its hook, the sampling options.
 * False (reported) on a bad option or no memory. */
bool montecarlo_init(MonteCarlo *mc, const Scene *scene, Surfaces surfaces, const Options *opts)
{
    *mc = (MonteCarlo){.camera = camera_make(&scene->camera),
                       .pixel_side = opts->samples,
                       .light_side = opts->light_samples,
                       .seed = (uint64_t)opts->seed};
    if (!strata_sampling_from_name(opts->sampling_name, &mc->sampling)) {
        fprintf(stderr, "raytra: unknown sampling '%s' (random, jittered or correlated)\n",
                opts->sampling_name);
        return false;
    }
    if (mc->pixel_side < 1 || mc->pixel_side > MONTECARLO_MAX_SIDE || mc->light_side < 1 ||
        mc->light_side > MONTECARLO_MAX_SIDE) {
        fprintf(stderr, "raytra: P and S must be from 1 to %d\n", MONTECARLO_MAX_SIDE);
        return false;
    }
    /* The point and directional lights, and the ambient light, are 1.3's business: a
     * copy of the scene that shares everything but its list of lights. */
    mc->point_scene = *scene;
    mc->point_scene.lights = malloc(sizeof(Light) * (size_t)(scene->light_count + 1));
    if (mc->point_scene.lights == NULL)
        return false;
    mc->point_scene.light_count = 0;
    for (int k = 0; k < scene->light_count; k++)
        if (scene->lights[k].kind != LIGHT_AREA)
            mc->point_scene.lights[mc->point_scene.light_count++] = scene->lights[k];
    mc->below = below_make(scene, surfaces, opts);
    below_tracer(&mc->below)->direct = montecarlo_direct_radiance;
    mc->point_lights = below_make(&mc->point_scene, surfaces, opts);
    return true;
}

/* Tells --view what the camera ray through the centre of pixel (i, j) meets first. */
void montecarlo_probe(const MonteCarlo *mc, int i, int j, Probe *probe)
{
    trace_probe(below_tracer(&mc->below), camera_ray(&mc->camera, i + 0.5, j + 0.5), probe);
}

/* Frees what montecarlo_init allocated. */
void montecarlo_free(MonteCarlo *mc)
{
    free(mc->point_scene.lights);
    mc->point_scene.lights = NULL;
}

/* starter: todo */
/* excerpt: area-radiance */
/* Returns the light that hit's surface reflects along r from the square light: S x S
 * shadow rays to points spread over it, each a point light of 1/S^2 of its colour. */
Color montecarlo_area_radiance(const MonteCarlo *mc, const Light *light, const Hit *hit, Ray r,
                                int depth, Path *path)
{
    const Sample *sample = path->sample;
    const Tracer *tr = below_tracer(&mc->below);
    const Scene *scene = tr->scene;
    const Material *m = shade_material(scene, hit, tr->two_sided);
    Vec3 n = shade_normal(hit);
    Vec3 v = vec3_neg(r.dir);
    int side = mc->light_side, count = side * side;
    /* Correlated strata: with one shadow ray per hit, the shadow ray of the pixel's
     * sub-pixel k goes to light stratum pi(k), so the pixel's P^2 rays cover the light. */
    bool follows_pixel = count == 1 && sample->strata_side > 1;
    Color sum = color(0, 0, 0);
    for (int q = 0; q < count; q++) {
        double ru, rv;
        if (follows_pixel)
            strata_point(SAMPLING_JITTERED, sample->rng, sample->stratum, sample->strata_side,
                         &ru, &rv);
        else
            strata_point(mc->sampling, sample->rng, q, side, &ru, &rv);
        Incident in = area_incident(light, area_point(light, ru, rv), hit->point, count,
                                    scene_light_falls_off(scene));
        /* As for a point light: no shadow ray where the light adds nothing anyway. */
        if (color_is_black(in.radiance) || vec3_dot(n, in.dir) <= 0) {
            explain_line(tr->explain, depth + 1, "area light sample %d of 0 to %d: faces away", q,
                         count - 1);
            continue;
        }
        Color through = below_light_through(&mc->below, hit, r, &in, path);
        if (color_is_black(through)) {
            explain_line(tr->explain, depth + 1, "area light sample %d of 0 to %d: in shadow", q,
                         count - 1);
            continue;
        }
        Color c = color_mul(shade_blinn_phong(m, n, v, &in), through);
        explain_line(tr->explain, depth + 1,
                     "area light sample %d of 0 to %d: Blinn-Phong = (%.6g, %.6g, %.6g)", q,
                     count - 1, c.r, c.g, c.b);
        sum = color_add(sum, c);
    }
    explain_color(tr->explain, depth + 1, "area light", sum);
    return sum;
}
/* end excerpt: area-radiance */

/* starter: todo */
/* excerpt: montecarlo-direct-radiance */
/* Returns the light that hit's surface reflects along r straight from the lights: the
 * part below's direct light for the ambient, point and directional lights, plus every
 * area light sampled. Replaces 1.3's direct_radiance as the tracer's direct hook. */
Color montecarlo_direct_radiance(const Tracer *tr, const Hit *hit, Ray r, int depth, Path *path)
{
    /* tr begins a MonteCarlo (montecarlo_init plugs this hook in there alone). */
    const MonteCarlo *mc = (const MonteCarlo *)tr;
    Color sum = BELOW_DIRECT(below_tracer(&mc->point_lights), hit, r, depth, path);
    const Scene *scene = tr->scene;
    for (int k = 0; k < scene->light_count; k++)
        if (scene->lights[k].kind == LIGHT_AREA)
            sum = color_add(sum,
                            montecarlo_area_radiance(mc, &scene->lights[k], hit, r, depth, path));
    return sum;
}
/* end excerpt: montecarlo-direct-radiance */

/* starter: todo */
/* excerpt: montecarlo-pixel */
/* Returns the summed radiance of samples first to last - 1 of the P x P rays through
 * pixel (i, j): ray k through a random point of sub-square k (jittered; k counts the
 * sub-squares row by row from the pixel's bottom left), or through its centre when P = 1.
 * The lecture's one ray per pixel, at u = l + (r - l)(i + 0.5)/n_x, samples the image at
 * a point: slide 38 ("relationship of (i, j) th pixel in image plane to u, v").
 * One point a pixel aliases: slide 75 ("note aliasing"). P x P points average the
 * pixel's area. Each ray has its own random numbers, from (seed, pixel, k) alone, so
 * that no pixel depends on which thread renders it, or when, and ray k is the same
 * whether it is traced with the others or alone (--trace-pixel X,Y@k). */
static Color sum_samples(const MonteCarlo *mc, int i, int j, int first, int last, RayStats *stats)
{
    int side = mc->pixel_side, count = side * side;
    uint64_t key = rng_hash(rng_hash(mc->seed) ^ ((uint64_t)(uint32_t)j << 32 | (uint32_t)i));
    /* The per-pixel permutation pi of the light strata, for correlated sampling. */
    bool correlated = mc->sampling == SAMPLING_CORRELATED && mc->light_side == 1 && side > 1;
    int perm[MONTECARLO_MAX_SIDE * MONTECARLO_MAX_SIDE];
    if (correlated) {
        Rng shuffle = rng_make(key, 0);
        strata_shuffle(&shuffle, perm, count);
    }
    const Explain *explain = below_tracer(&mc->below)->explain;
    Color sum = color(0, 0, 0);
    for (int k = first; k < last; k++) {
        Rng rng = rng_make(key, (uint64_t)k + 1);
        double x = i + 0.5, y = j + 0.5;
        if (side > 1) {
            double du, dv;
            strata_point(mc->sampling, &rng, k, side, &du, &dv);
            x = i + du;
            y = j + dv;
        }
        Sample sample = {.rng = &rng,
                         .stratum = correlated ? perm[k] : 0,
                         .strata_side = correlated ? side : 0};
        Path path = {.stats = stats, .sample = &sample};
        Ray r = camera_ray(&mc->camera, x, y);
        stats->rays[RAY_PRIMARY]++;
        if (side > 1 && mc->sampling != SAMPLING_RANDOM)
            explain_line(explain, 0,
                         "sample %d of 0 to %d: in sub-square %d from the left, %d from the "
                         "bottom, at image point (%.6f, %.6f)",
                         k, count - 1, k % side, k / side, x, y);
        else
            explain_line(explain, 0, "sample %d of 0 to %d: at image point (%.6f, %.6f)", k,
                         count - 1, x, y);
        explain_ray(explain, 0, "camera", r);
        sum = color_add(sum, below_radiance(&mc->below, r, 0, &path));
    }
    return sum;
}
/* end excerpt: montecarlo-pixel */

/* excerpt: montecarlo-mean */
/* Returns the colour of pixel (i, j): the mean radiance of its P x P rays. The box
 * filter: every ray through the pixel counts 1/P^2. */
Color montecarlo_pixel(const MonteCarlo *mc, int i, int j, RayStats *stats)
{
    int count = mc->pixel_side * mc->pixel_side;
    return color_scale(sum_samples(mc, i, j, 0, count, stats), 1.0 / count);
}
/* end excerpt: montecarlo-mean */

/* Returns the radiance of ray k alone of pixel (i, j), the very ray and random numbers
 * it has in montecarlo_pixel: --trace-pixel X,Y@k. */
Color montecarlo_sample(const MonteCarlo *mc, int i, int j, int k, RayStats *stats)
{
    return sum_samples(mc, i, j, k, k + 1, stats);
}
