/* raytra.c: part 1.6, Monte Carlo ray tracing: jittered rays per pixel, soft shadows. */
#include <stdlib.h>

#include "app.h"
#include "montecarlo.h"
#include "accel.h"

/* The sampling, and the BVH behind it. */
typedef struct {
    MonteCarlo mc;
    Accel accel;
} Part16;

/* Builds part 1.4's BVH, and over it the camera, the tracer and the sampling of the scene
 * (montecarlo_init). */
static bool setup(const Scene *scene, const Options *opts, void **ctx)
{
    Part16 *part = malloc(sizeof *part);
    if (part == NULL || !accel_build(&part->accel, scene, ACCEL_BVH)) {
        free(part);
        return false;
    }
    if (!montecarlo_init(&part->mc, scene, accel_surfaces(&part->accel), opts)) {
        accel_free(&part->accel);
        free(part);
        return false;
    }
    *ctx = part;
    return true;
}

/* Part 1.6's pixel: the mean of its P x P samples. */
static Color sample_pixel(const void *ctx, int i, int j, RayStats *stats)
{
    return montecarlo_pixel(&((const Part16 *)ctx)->mc, i, j, stats);
}

/* Part 1.6's sample k alone of pixel (i, j), for --trace-pixel X,Y@k. */
static Color one_sample(const void *ctx, int i, int j, int k, RayStats *stats)
{
    return montecarlo_sample(&((const Part16 *)ctx)->mc, i, j, k, stats);
}

/* Tells --view what the camera ray through the pixel's centre meets first, and for
 * box-tests how many of the BVH's boxes and primitives it was tested against. */
static void probe_pixel(const void *ctx, int i, int j, Probe *probe)
{
    montecarlo_probe(&((const Part16 *)ctx)->mc, i, j, probe);
}

/* Frees the part's state. */
static void cleanup(void *ctx)
{
    Part16 *part = ctx;
    accel_free(&part->accel);
    free(part);
}

/* Estimates the lines --trace-pixel prints: P x P camera rays a pixel (one for a sample
 * alone), S x S samples of each area light at every hit. */
static void trace_lines(const void *ctx, int sample, double *fewest, double *most)
{
    const MonteCarlo *mc = &((const Part16 *)ctx)->mc;
    double rays = sample < 0 ? (double)mc->pixel_side * mc->pixel_side : 1;
    tracer_trace_lines(&mc->tracer, rays, (double)mc->light_side * mc->light_side, fewest, most);
}

static const Program program = {
    .cli = {.part = "1.6-monte-carlo",
            .options = montecarlo_part_options,
            .purpose = "Monte Carlo ray tracing: P x P jittered rays per pixel, S x S shadow "
                       "rays per area light"},
    .features = MONTECARLO_FEATURES,
    .setup = setup,
    .pixel = sample_pixel,
    .sample = one_sample,
    .samples_option = "samples",
    .probe = probe_pixel,
    .views = 1u << VIEW_LIGHT_COUNT | 1u << VIEW_BOX_TESTS,
    .trace_lines = trace_lines,
    .cleanup = cleanup,
};

/* Renders a scene by the rules of part 1.6. */
int main(int argc, char **argv)
{
    return app_main(&program, argc, argv);
}
