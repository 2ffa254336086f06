/* raytra.c: part 1.6, Monte Carlo ray tracing: jittered rays per pixel, soft shadows. */
#include <stdlib.h>

#include "app.h"
#include "montecarlo.h"
#include "surfaces.h"

/* excerpt: setup */
/* Builds the camera, the tracer and the sampling of the scene. The geometry comes from
 * the parts below (1.3's brute force; 1.4's BVH, accel_surfaces, once merged), and the
 * tracing itself from below.h. */
static bool setup(const Scene *scene, const Options *opts, void **ctx)
{
    MonteCarlo *mc = malloc(sizeof *mc);
    if (mc == NULL)
        return false;
    Surfaces surfaces = surfaces_brute_force(scene);
    if (!montecarlo_init(mc, scene, surfaces, opts)) {
        free(mc);
        return false;
    }
    *ctx = mc;
    return true;
}
/* end excerpt: setup */

/* Part 1.6's pixel: the mean of its P x P samples. */
static Color sample_pixel(const void *ctx, int i, int j, RayStats *stats)
{
    return montecarlo_pixel(ctx, i, j, stats);
}

/* Tells --view what the camera ray meets first. */
static void probe_pixel(const void *ctx, int i, int j, Probe *probe)
{
    montecarlo_probe(ctx, i, j, probe);
}

/* Frees the part's state. */
static void cleanup(void *ctx)
{
    montecarlo_free(ctx);
    free(ctx);
}

static const Program program = {
    .cli = {.part = "1.6-monte-carlo",
            .purpose = "Monte Carlo ray tracing: P x P jittered rays per pixel, S x S shadow "
                       "rays per area light"},
    .features = FEATURE_SPHERES | FEATURE_PLANES | FEATURE_TRIANGLES | FEATURE_POINT_LIGHTS |
                FEATURE_DIRECTIONAL_LIGHTS | FEATURE_AREA_LIGHTS | FEATURE_AMBIENT_LIGHT |
                FEATURE_MIRRORS | FEATURE_SHADING,
    .setup = setup,
    .pixel = sample_pixel,
    .probe = probe_pixel,
    .cleanup = cleanup,
};

/* Renders a scene by the rules of part 1.6. */
int main(int argc, char **argv)
{
    return app_main(&program, argc, argv);
}
