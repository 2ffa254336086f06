/* montecarlo.c: the pixel as the mean of P x P jittered rays, area lights as S x S shadow rays. */
#include "montecarlo.h"

#include <stdio.h>

#include "area.h"
#include "direct.h"
#include "transmit.h"

/* Sets up mc to render scene, finding hits with surfaces: the camera, part 1.3's tracer
 * (which each sample's extends), part 1.5's Refractor, the sampling options. False
 * (reported) on a bad option. */
bool montecarlo_init(MonteCarlo *mc, const Scene *scene, Surfaces surfaces, const Options *opts)
{
    *mc = (MonteCarlo){.tracer = tracer_make(scene, surfaces, opts, &direct_hooks, NULL),
                       .camera = camera_make(&scene->camera),
                       .pixel_side = cli_int(opts, "samples"),
                       .light_side = cli_int(opts, "light-samples"),
                       .seed = (uint64_t)cli_int(opts, "seed")};
    const char *sampling_name = cli_text(opts, "sampling");
    if (!strata_sampling_from_name(sampling_name, &mc->sampling)) {
        fprintf(stderr, "raytra: unknown sampling '%s' (random, jittered or correlated)\n",
                sampling_name);
        return false;
    }
    if (mc->pixel_side < 1 || mc->pixel_side > MONTECARLO_MAX_SIDE || mc->light_side < 1 ||
        mc->light_side > MONTECARLO_MAX_SIDE) {
        fprintf(stderr, "raytra: P and S must be from 1 to %d\n", MONTECARLO_MAX_SIDE);
        return false;
    }
    return refract_init(&mc->refractor, scene, opts);
}

/* Tells --view what the camera ray through the centre of pixel (i, j) meets first. */
void montecarlo_probe(const MonteCarlo *mc, int i, int j, Probe *probe)
{
    trace_probe(&mc->tracer, camera_ray(&mc->camera, i + 0.5, j + 0.5), MONTECARLO_FEATURES, probe);
}

/* starter: todo */
/* excerpt: light-point */
/* Returns in (*ru, *rv) the point in [0,1)^2 of light sample q of the S x S a hit sends
 * to an area light, drawn from the path's random numbers: one in each of S x S
 * sub-squares (stratified), or, with one shadow ray per hit in correlated sampling,
 * in the light stratum pi(k) of the pixel's sub-pixel k, so that the pixel's P^2 rays
 * cover the light. */
void montecarlo_light_point(const MonteCarlo *mc, const Sample *sample, int q, double *ru,
                            double *rv)
{
    if (mc->light_side == 1 && sample->strata_side > 1)
        strata_point(SAMPLING_JITTERED, sample->rng, sample->stratum, sample->strata_side, ru, rv);
    else
        strata_point(mc->sampling, sample->rng, q, mc->light_side, ru, rv);
}
/* end excerpt: light-point */

/* Returns the light that hit's surface reflects along r from the square light: S x S
 * shadow rays to points spread over it (montecarlo_light_point, area_point), each a
 * point light of 1/S^2 of its colour (area_incident), lit as part 1.3 lights a point
 * light (direct_incident). */
Color montecarlo_area_radiance(const Sample *sample, const Tracer *tr, const Light *light,
                               const Hit *hit, Ray r, int depth, Path *path)
{
    const MonteCarlo *mc = sample->mc;
    int count = mc->light_side * mc->light_side;
    Color sum = color(0, 0, 0);
    for (int q = 0; q < count; q++) {
        double ru = 0, rv = 0;
        montecarlo_light_point(mc, sample, q, &ru, &rv);
        Vec3 at = area_point(light, ru, rv);
        if (tr->explain != NULL) {
            char p[96];
            explain_line(tr->explain, depth + 2, "area light sample %d of 0 to %d at %s", q,
                         count - 1, explain_vec3(at, p, sizeof p));
        }
        Incident in = area_incident(light, at, hit->point, count, scene_light_falls_off(tr->scene));
        /* depth + 1: told one level deeper, under its sample. */
        Color c = direct_incident(tr, hit, r, &in, depth + 1, path);
        explain_line(tr->explain, depth + 3,
                     "area light sample %d of 0 to %d adds (%.6g, %.6g, %.6g)", q, count - 1, c.r,
                     c.g, c.b);
        sum = color_add(sum, c);
    }
    return sum;
}

/* Part 1.6's light hook: an area light sampled by S x S shadow rays; a point or
 * directional light as part 1.3 lights it (direct_incident). ctx is the Sample. */
Color montecarlo_light(const void *ctx, const Tracer *tr, const Hit *hit, Ray r, const Light *light,
                       int depth, Path *path)
{
    if (light->kind == LIGHT_AREA)
        return montecarlo_area_radiance(ctx, tr, light, hit, r, depth, path);
    Incident in = light_incident(light, hit->point, scene_light_falls_off(tr->scene));
    return direct_incident(tr, hit, r, &in, depth, path);
}

/* Part 1.6's through hook: part 1.5's transmit_light, handed part 1.5's context, the
 * Refractor of the Sample ctx. */
static Color montecarlo_through(const void *ctx, const Tracer *tr, const Hit *hit, Ray r,
                                const Incident *in, int depth, Path *path)
{
    const Sample *sample = ctx;
    return transmit_light(&sample->mc->refractor, tr, hit, r, in, depth, path);
}

/* Part 1.6's hooks, which each sample's tracer is handed with the Sample as their context:
 * area lights sampled, and shadows through glass as in part 1.5. */
const TracerHooks montecarlo_hooks = {.light = montecarlo_light, .through = montecarlo_through};

/* starter: todo */
/* Returns in (*x, *y) the image point of ray k of the P x P rays through pixel (i, j):
 * a random point of sub-square k (jittered; k counts the sub-squares row by row from
 * the pixel's bottom left), drawn from rng, or the pixel's centre when P = 1.
 * The lecture's one ray per pixel, at u = l + (r - l)(i + 0.5)/n_x, samples the image at
 * a point: slide 38 ("relationship of (i, j) th pixel in image plane to u, v").
 * One point a pixel aliases: slide 75 ("note aliasing"). P x P points average the
 * pixel's area. */
void montecarlo_point(const MonteCarlo *mc, Rng *rng, int i, int j, int k, double *x, double *y)
{
    *x = i + 0.5;
    *y = j + 0.5;
    if (mc->pixel_side > 1) {
        double du, dv;
        strata_point(mc->sampling, rng, k, mc->pixel_side, &du, &dv);
        *x = i + du;
        *y = j + dv;
    }
}

/* Prints, for --trace-pixel, which of the pixel's samples k is and where it goes. */
static void explain_sample(const Explain *e, const MonteCarlo *mc, int k, double x, double y)
{
    int side = mc->pixel_side, count = side * side;
    if (side > 1 && mc->sampling != SAMPLING_RANDOM)
        explain_line(e, 0,
                     "sample %d of 0 to %d: in sub-square %d from the left, %d from the "
                     "bottom, at image point (%.6f, %.6f)",
                     k, count - 1, k % side, k / side, x, y);
    else
        explain_line(e, 0, "sample %d of 0 to %d: at image point (%.6f, %.6f)", k, count - 1, x, y);
}

/* Returns the summed radiance of samples first to last - 1 of the P x P rays through
 * pixel (i, j), each through its own point (montecarlo_point). Each ray has its own
 * random numbers, from (seed, pixel, k) alone, so that no pixel depends on which thread
 * renders it, or when, and ray k is the same whether it is traced with the others or
 * alone (--trace-pixel X,Y@k). */
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
    Color sum = color(0, 0, 0);
    for (int k = first; k < last; k++) {
        Rng rng = rng_make(key, (uint64_t)k + 1);
        double x = 0, y = 0;
        montecarlo_point(mc, &rng, i, j, k, &x, &y);
        explain_sample(mc->tracer.explain, mc, k, x, y);
        Sample sample = {.mc = mc,
                         .rng = &rng,
                         .stratum = correlated ? perm[k] : 0,
                         .strata_side = correlated ? side : 0};
        /* The sample's own tracer: its hooks draw from the sample's random numbers. */
        Tracer tr = tracer_extend(&mc->tracer, &montecarlo_hooks, &sample);
        Path path = {.stats = stats};
        Ray r = camera_ray(&mc->camera, x, y);
        sum = color_add(sum, refract_trace(&mc->refractor, &tr, r, RAY_PRIMARY, 0, 1, &path));
    }
    return sum;
}

/* starter: todo */
/* Returns the colour of pixel (i, j): the mean radiance of its P x P rays. The box
 * filter: every ray through the pixel counts 1/P^2. */
Color montecarlo_pixel(const MonteCarlo *mc, int i, int j, RayStats *stats)
{
    int count = mc->pixel_side * mc->pixel_side;
    return color_scale(sum_samples(mc, i, j, 0, count, stats), 1.0 / count);
}

/* Returns the radiance of ray k alone of pixel (i, j), the very ray and random numbers
 * it has in montecarlo_pixel: --trace-pixel X,Y@k. */
Color montecarlo_sample(const MonteCarlo *mc, int i, int j, int k, RayStats *stats)
{
    return sum_samples(mc, i, j, k, k + 1, stats);
}
