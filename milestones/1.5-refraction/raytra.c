/* raytra.c: part 1.5: glass that reflects and refracts light, and absorbs it, on top of part 1.3. */
#include <stdio.h>
#include <stdlib.h>

#include "accel.h"
#include "app.h"
#include "refract.h"
#include "solid.h"
#include "trace.h"

/* What every pixel reads: the camera and the tracer, as part 1.3's TraceView, the
 * tracer's context (the Refractor), and the geometry behind it. */
typedef struct {
    TraceView view;
    Refractor refractor;
    Tracer tracer;
    Accel accel;
} Part15;

/* Frees the part's state. */
static void cleanup(void *ctx)
{
    Part15 *part = ((TraceView *)ctx)->part;
    accel_free(&part->accel);
    free(part);
}

/* Builds part 1.4's BVH (or the boxes of MODE), the Refractor from the command line, the
 * tracer with this part's hooks and the Refractor as their context, and the camera; then
 * checks the glass meshes. */
static bool setup(const Scene *scene, const Options *opts, void **ctx)
{
    Part15 *part = malloc(sizeof *part);
    if (part == NULL)
        return false;
    if (!accel_build(&part->accel, scene, accel_mode(opts))) {
        free(part);
        return false;
    }
    part->view = (TraceView){camera_make(&scene->camera), &part->tracer, part};
    if (!refract_init(&part->refractor, scene, opts)) {
        cleanup(&part->view);
        return false;
    }
    part->tracer =
        tracer_make(scene, accel_surfaces(&part->accel), opts, &refract_hooks, &part->refractor);
    solid_warn(scene, stderr);
    *ctx = &part->view;
    return true;
}

/* Returns the radiance along the camera ray through the centre of pixel (i, j): part
 * 1.5's pixel, which traces with refract_trace, a whole share of its pixel. */
static Color pixel(const void *ctx, int i, int j, RayStats *stats)
{
    const TraceView *view = ctx;
    const Part15 *part = view->part;
    Path path = {.stats = stats};
    Ray r = camera_ray(&view->camera, i + 0.5, j + 0.5);
    return refract_trace(&part->refractor, view->tracer, r, RAY_PRIMARY, 0, 1, &path);
}

static const Program program = {
    .cli = {.part = "1.5-refraction",
            .options = refract_part_options,
            .purpose = "recursive ray tracing with glass: Fresnel reflection, refraction and "
                       "absorption"},
    .features = TRACER_FEATURES | FEATURE_REFRACTION,
    .setup = setup,
    .pixel = pixel,
    .probe = trace_view_probe,
    .views = 1u << VIEW_LIGHT_COUNT | 1u << VIEW_BOX_TESTS,
    .trace_lines = trace_view_lines,
    .cleanup = cleanup,
};

/* Renders a scene by the rules of part 1.5. */
int main(int argc, char **argv)
{
    return app_main(&program, argc, argv);
}
