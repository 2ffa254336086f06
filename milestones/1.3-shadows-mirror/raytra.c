/* raytra.c: part 1.3: shadows, ambient light and mirror reflection, by recursive ray tracing. */
#include <math.h>
#include <stdlib.h>

#include "app.h"
#include "secondary.h"
#include "trace.h"
#include "view.h"

/* What every pixel reads: the camera, and the tracer with its scene and settings. */
typedef struct {
    View view;
    Tracer tracer;
} Part13;

/* Builds the camera and the tracer of the scene. */
static bool setup(const Scene *scene, const Options *opts, void **ctx)
{
    Part13 *part = malloc(sizeof *part);
    if (part == NULL)
        return false;
    part->view = (View){camera_make(&scene->camera), scene, opts};
    part->tracer = tracer_make(scene, surfaces_brute_force(scene), opts);
    *ctx = part;
    return true;
}

/* Part 1.3's pixel: the radiance along the primary ray through its centre. */
static Color trace_pixel(const void *ctx, int i, int j, RayStats *stats)
{
    const Part13 *part = ctx;
    return trace_camera_pixel(&part->tracer, &part->view.camera, i, j, stats);
}

/* Tells --view what the camera ray meets first. */
static void probe_pixel(const void *ctx, int i, int j, Probe *probe)
{
    const Part13 *part = ctx;
    trace_probe(&part->tracer, camera_ray(&part->view.camera, i + 0.5, j + 0.5), probe);
}

/* Estimates the lines --trace-pixel prints: one camera ray a pixel. */
static void trace_lines(const void *ctx, int sample, double *fewest, double *most)
{
    (void)sample;
    tracer_trace_lines(&((const Part13 *)ctx)->tracer, 1, 0, fewest, most);
}

static const Program program = {
    .cli = {.part = "1.3-shadows-mirror",
            .options = trace_part_options,
            .purpose = "Blinn-Phong shading with shadows, ambient light and mirror reflection"},
    .features = TRACER_FEATURES,
    .setup = setup,
    .pixel = trace_pixel,
    .probe = probe_pixel,
    .views = 1u << VIEW_LIGHT_COUNT,
    .trace_lines = trace_lines,
    .cleanup = free,
};

/* Renders a scene by the rules of part 1.3. */
int main(int argc, char **argv)
{
    return app_main(&program, argc, argv);
}
