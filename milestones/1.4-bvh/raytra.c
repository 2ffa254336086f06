/* raytra.c: part 1.4: part 1.3's tracer behind bounding boxes and a bounding volume hierarchy. */
#include <stdio.h>
#include <stdlib.h>

#include "accel.h"
#include "app.h"
#include "direct.h"
#include "trace.h"

/* What every pixel reads (part 1.3's TraceView), the tracer, and the geometry behind it. */
typedef struct {
    TraceView view;
    Tracer tracer;
    Accel accel;
} Part14;

/* Builds the camera, the boxes or the BVH of the mode (the course's third argument,
 * raytra scene_file output_image [0|1|2|3], or --mode N), and part 1.3's tracer on top. */
static bool setup(const Scene *scene, const Options *opts, void **ctx)
{
    Part14 *part = malloc(sizeof *part);
    if (part == NULL)
        return false;
    if (!accel_build(&part->accel, scene, accel_mode(opts))) {
        free(part);
        return false;
    }
    part->tracer = tracer_make(scene, accel_surfaces(&part->accel), opts, &direct_hooks, NULL);
    part->view = (TraceView){camera_make(&scene->camera), &part->tracer, part};
    *ctx = &part->view;
    return true;
}

/* Counts the BVH's leaves of no primitive (the grader reads them): of node_count + 1, the unnamed. */
static int empty_leaves(const Bvh *b)
{
    int named = 0;
    for (int k = 0; k < 2 * b->node_count; k++)
        named += b->nodes[k / 2].child[k % 2].count > 0;
    return b->node_count > 0 ? b->node_count + 1 - named : 0;
}

/* Prints the size, shape and build time of the BVH (modes 2 and 3) after the summary line. */
static void report(const void *ctx)
{
    const Accel *a = &((const Part14 *)((const TraceView *)ctx)->part)->accel;
    const Bvh *b = &a->bvh;
    if (a->mode == ACCEL_LEAF_BOXES || a->mode == ACCEL_BVH)
        fprintf(stderr,
                "raytra: mode %d: BVH of %d primitives: %d interior nodes, %d leaves (%d empty), "
                "depth %d, %.1f bytes per primitive, built in %.1f ms\n",
                a->mode, b->prim_count, b->node_count, b->node_count + (b->prim_count > 0),
                empty_leaves(b), b->depth,
                b->prim_count > 0 ? (double)bvh_bytes(b) / b->prim_count : 0.0,
                a->build_seconds * 1e3);
}

/* Frees the part's state. */
static void cleanup(void *ctx)
{
    Part14 *part = ((TraceView *)ctx)->part;
    accel_free(&part->accel);
    free(part);
}

static const Program program = {
    .cli = {.part = "1.4-bvh",
            .options = accel_part_options,
            .purpose = "part 1.3's ray tracer, accelerated by bounding boxes and a BVH"},
    .features = TRACER_FEATURES,
    .setup = setup,
    .pixel = trace_view_pixel,
    .probe = trace_view_probe,
    .views = 1u << VIEW_LIGHT_COUNT | 1u << VIEW_BOX_TESTS,
    .report = report,
    .trace_lines = trace_view_lines,
    .cleanup = cleanup,
};

/* Renders a scene by the rules of part 1.4. */
int main(int argc, char **argv)
{
    return app_main(&program, argc, argv);
}
