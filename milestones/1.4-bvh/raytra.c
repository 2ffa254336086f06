/* raytra.c: part 1.4: part 1.3's tracer behind bounding boxes and a bounding volume hierarchy. */
#include <stdio.h>
#include <stdlib.h>

#include "accel.h"
#include "app.h"
#include "trace.h"
#include "view.h"

/* What every pixel reads: the camera, the tracer, and the geometry behind its Surfaces. */
typedef struct {
    View view;
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
    part->view = (View){camera_make(&scene->camera), scene, opts};
    part->tracer = tracer_make(scene, accel_surfaces(&part->accel), opts);
    *ctx = part;
    return true;
}

/* Part 1.4's pixel: part 1.3's, with the mode's Surfaces behind the tracer. */
static Color trace_pixel(const void *ctx, int i, int j, RayStats *stats)
{
    const Part14 *part = ctx;
    return trace_camera_pixel(&part->tracer, &part->view.camera, i, j, stats);
}

/* Tells --view what the camera ray meets first, and for box-tests how many boxes and
 * primitives it was tested against (accel_count_tests). */
static void probe_pixel(const void *ctx, int i, int j, Probe *probe)
{
    const Part14 *part = ctx;
    Ray r = camera_ray(&part->view.camera, i + 0.5, j + 0.5);
    trace_probe(&part->tracer, r, probe);
    probe->tests = accel_count_tests(&part->accel, r);
}

/* Prints the size and build time of the BVH (modes 2 and 3) after the summary line. */
static void report(const void *ctx, const RenderResult *result)
{
    (void)result;
    const Accel *a = &((const Part14 *)ctx)->accel;
    const Bvh *b = &a->bvh;
    if (a->mode == ACCEL_LEAF_BOXES || a->mode == ACCEL_BVH)
        fprintf(stderr,
                "raytra: mode %d: BVH of %d primitives: %d interior nodes, %d leaves, depth %d, "
                "%.1f bytes per primitive, built in %.1f ms\n",
                a->mode, b->prim_count, b->node_count, b->node_count + (b->prim_count > 0),
                b->depth, b->prim_count > 0 ? (double)bvh_bytes(b) / b->prim_count : 0.0,
                a->build_seconds * 1e3);
}

/* Frees the part's state. */
static void cleanup(void *ctx)
{
    Part14 *part = ctx;
    accel_free(&part->accel);
    free(part);
}

/* Estimates the lines --trace-pixel prints: one camera ray a pixel. */
static void trace_lines(const void *ctx, int sample, double *fewest, double *most)
{
    (void)sample;
    tracer_trace_lines(&((const Part14 *)ctx)->tracer, 1, 0, fewest, most);
}

static const Program program = {
    .cli = {.part = "1.4-bvh",
            .options = accel_part_options,
            .purpose = "part 1.3's ray tracer, accelerated by bounding boxes and a BVH"},
    .features = TRACER_FEATURES,
    .setup = setup,
    .pixel = trace_pixel,
    .probe = probe_pixel,
    .views = 1u << VIEW_LIGHT_COUNT | 1u << VIEW_BOX_TESTS,
    .report = report,
    .trace_lines = trace_lines,
    .cleanup = cleanup,
};

/* Renders a scene by the rules of part 1.4. */
int main(int argc, char **argv)
{
    return app_main(&program, argc, argv);
}
