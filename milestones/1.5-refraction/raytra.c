/* raytra.c: part 1.5: glass that reflects and refracts light, and absorbs it, on top of part 1.3. */
#include <stdio.h>
#include <stdlib.h>

#include "accel.h"
#include "app.h"
#include "refract.h"
#include "solid.h"
#include "view.h"

/* What every pixel reads: the camera, the tracer, and the geometry behind its Surfaces. */
typedef struct {
    View view;
    Refractor refractor;
    Accel accel;
} Part15;

/* Frees the part's state. */
static void cleanup(void *ctx)
{
    Part15 *part = ctx;
    accel_free(&part->accel);
    free(part);
}

/* Builds the camera, part 1.4's BVH (or the boxes of MODE) and the tracer of the scene,
 * then checks the glass meshes. */
static bool setup(const Scene *scene, const Options *opts, void **ctx)
{
    Part15 *part = malloc(sizeof *part);
    if (part == NULL)
        return false;
    if (!accel_build(&part->accel, scene, accel_mode(opts))) {
        free(part);
        return false;
    }
    if (!refract_init(&part->refractor, scene, accel_surfaces(&part->accel), opts)) {
        cleanup(part);
        return false;
    }
    solid_warn(scene, stderr);
    part->view = (View){camera_make(&scene->camera), scene, opts};
    *ctx = part;
    return true;
}

/* excerpt: refract-pixel */
/* Part 1.5's pixel: part 1.3's, the radiance along the primary ray through its centre,
 * with the Refractor's hooks in the tracer. */
static Color refract_pixel(const void *ctx, int i, int j, RayStats *stats)
{
    const Part15 *part = ctx;
    return trace_camera_pixel(&part->refractor.tracer, &part->view.camera, i, j, stats);
}
/* end excerpt: refract-pixel */

/* Tells --view what the camera ray meets first, as part 1.3 does, and for box-tests how
 * many boxes and primitives it was tested against, as part 1.4 does. */
static void probe_pixel(const void *ctx, int i, int j, Probe *probe)
{
    const Part15 *part = ctx;
    Ray r = camera_ray(&part->view.camera, i + 0.5, j + 0.5);
    trace_probe(&part->refractor.tracer, r, probe);
    probe->tests = accel_count_tests(&part->accel, r);
}

/* Estimates the lines --trace-pixel prints: one camera ray a pixel. */
static void trace_lines(const void *ctx, int sample, double *fewest, double *most)
{
    (void)sample;
    tracer_trace_lines(&((const Part15 *)ctx)->refractor.tracer, 1, 0, fewest, most);
}

static const Program program = {
    .cli = {.part = "1.5-refraction",
            .options = refract_part_options,
            .purpose = "recursive ray tracing with glass: Fresnel reflection, refraction and "
                       "absorption"},
    .features = TRACER_FEATURES | FEATURE_REFRACTION,
    .setup = setup,
    .pixel = refract_pixel,
    .probe = probe_pixel,
    .views = 1u << VIEW_LIGHT_COUNT | 1u << VIEW_BOX_TESTS,
    .trace_lines = trace_lines,
    .cleanup = cleanup,
};

/* Renders a scene by the rules of part 1.5. */
int main(int argc, char **argv)
{
    return app_main(&program, argc, argv);
}
