/* raytra.c: part 1.3: shadows, ambient light and mirror reflection, by recursive ray tracing. */
#include <stdlib.h>

#include "app.h"
#include "direct.h"
#include "trace.h"

/* What every pixel reads (the camera and the tracer, as a TraceView), and the tracer. */
typedef struct {
    TraceView view;
    Tracer tracer;
} Part13;

/* Builds the camera and the tracer of the scene; the context of the pixels is the view. */
static bool setup(const Scene *scene, const Options *opts, void **ctx)
{
    Part13 *part = malloc(sizeof *part);
    if (part == NULL)
        return false;
    part->tracer = tracer_make(scene, surfaces_brute_force(scene), opts, &direct_hooks, NULL);
    part->view = (TraceView){camera_make(&scene->camera), &part->tracer, part};
    *ctx = &part->view;
    return true;
}

/* Frees the part's state. */
static void cleanup(void *ctx)
{
    free(((TraceView *)ctx)->part);
}

static const Program program = {
    .cli = {.part = "1.3-shadows-mirror",
            .options = trace_part_options,
            .purpose = "Blinn-Phong shading with shadows, ambient light and mirror reflection"},
    .features = TRACER_FEATURES,
    .setup = setup,
    .pixel = trace_view_pixel,
    .probe = trace_view_probe,
    .views = 1u << VIEW_LIGHT_COUNT,
    .trace_lines = trace_view_lines,
    .cleanup = cleanup,
};

/* Renders a scene by the rules of part 1.3. */
int main(int argc, char **argv)
{
    return app_main(&program, argc, argv);
}
