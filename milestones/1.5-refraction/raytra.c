/* raytra.c: part 1.5: glass that reflects and refracts light, and absorbs it, on top of part 1.3. */
#include <stdio.h>
#include <stdlib.h>

#include "accel.h"
#include "app.h"
#include "refract.h"
#include "solid.h"

/* What every pixel reads (part 1.3's TraceView, of the Refractor's tracer), the tracer
 * with this part's hooks, and the geometry behind it. */
typedef struct {
    TraceView view;
    Refractor refractor;
    Accel accel;
} Part15;

/* Frees the part's state. */
static void cleanup(void *ctx)
{
    Part15 *part = ((TraceView *)ctx)->part;
    accel_free(&part->accel);
    free(part);
}

/* Builds part 1.4's BVH (or the boxes of MODE), the tracer of the scene with this part's
 * hooks (refract_init), and the camera through which part 1.3's pixel traces with it;
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
    part->view = (TraceView){camera_make(&scene->camera), &part->refractor.tracer, part};
    if (!refract_init(&part->refractor, scene, accel_surfaces(&part->accel), opts)) {
        cleanup(&part->view);
        return false;
    }
    solid_warn(scene, stderr);
    *ctx = &part->view;
    return true;
}

static const Program program = {
    .cli = {.part = "1.5-refraction",
            .options = refract_part_options,
            .purpose = "recursive ray tracing with glass: Fresnel reflection, refraction and "
                       "absorption"},
    .features = TRACER_FEATURES | FEATURE_REFRACTION,
    .setup = setup,
    .pixel = trace_view_pixel,
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
