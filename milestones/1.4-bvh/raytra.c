/* raytra.c: part 1.4: the tracer of part 1.3 behind bounding boxes and a bounding volume hierarchy. */
#include <stdio.h>
#include <stdlib.h>

#include "accel.h"
#include "app.h"
#include "light.h"
#include "secondary.h"
#include "trace.h"
#include "view.h"

static int mode = ACCEL_BVH;
static int max_depth = TRACE_MAX_DEPTH;
static bool two_sided;
static double offset = SECONDARY_OFFSET;

/* excerpt: mode-argument */
/* The course's command line, raytra scene_file output_image [0|1|2|3], and the same
 * as an option, --mode N. */
static const CliOption arguments[] = {
    {"MODE", 0, OPTION_INT, "N",
     "0: test every surface, each behind its own box; 1: draw every surface's box; "
     "2: draw the BVH's leaf boxes; 3 (the default): render with the BVH",
     &mode, 0, 3},
    {0},
};
/* end excerpt: mode-argument */

static const CliOption options[] = {
    {"mode", 0, OPTION_INT, "N", "the same as the MODE argument", &mode, 0, 3},
    {"max-depth", 0, OPTION_INT, "N",
     "follow at most N mirror reflections along a path (default 20; 0: none)", &max_depth, 0, 1000},
    {"two-sided", 0, OPTION_FLAG, NULL,
     "shade the backs of triangles and planes like their fronts, not flat yellow", &two_sided, 0,
     0},
    {"ray-offset", 0, OPTION_NUMBER, "F",
     "start shadow and reflected rays F times the size of the hit point's coordinates off "
     "the surface (default 2^-32); 0 shows shadow acne, large values detach shadows",
     &offset, 0, 1},
    {0},
};

/* What every pixel reads: the camera, the tracer, and the geometry behind its Surfaces. */
typedef struct {
    View view;
    Tracer tracer;
    Accel accel;
} Part14;

/* excerpt: setup */
/* Builds the camera, the boxes or the BVH of the mode, and part 1.3's tracer on top. */
static bool setup(const Scene *scene, void **ctx)
{
    Part14 *part = malloc(sizeof *part);
    if (part == NULL)
        return false;
    if (!accel_build(&part->accel, scene, (AccelMode)mode)) {
        fprintf(stderr, "raytra: not enough memory for the bounding boxes of %s\n", scene->path);
        accel_free(&part->accel);
        free(part);
        return false;
    }
    light_note_area_lights(scene);
    part->view = (View){camera_make(&scene->camera), scene};
    part->tracer = (Tracer){.scene = scene,
                            .surfaces = accel_surfaces(&part->accel),
                            .max_depth = max_depth,
                            .two_sided = two_sided,
                            .offset = offset};
    *ctx = part;
    return true;
}
/* end excerpt: setup */

/* Part 1.4's pixel: part 1.3's, with the mode's Surfaces behind the tracer. */
static Color trace_pixel(const void *ctx, int i, int j, RayStats *stats)
{
    const Part14 *part = ctx;
    Ray r = camera_ray(&part->view.camera, i + 0.5, j + 0.5);
    stats->rays[RAY_PRIMARY]++;
    return trace_radiance(&part->tracer, r, 0, stats);
}

/* Prints the size and build time of the BVH, or of the boxes, after the summary line. */
static void report(const void *ctx, const RenderResult *result)
{
    (void)result;
    const Accel *a = &((const Part14 *)ctx)->accel;
    if (a->mode == ACCEL_BOXED || a->mode == ACCEL_SURFACE_BOXES) {
        printf("mode %d: %d boxes, made in %.1f ms\n", a->mode,
               a->scene->sphere_count + a->scene->triangle_count, a->build_seconds * 1e3);
        return;
    }
    const Bvh *b = &a->bvh;
    printf("mode %d: BVH of %d primitives: %d nodes, %d leaves, depth %d, %.1f bytes per "
           "primitive, built in %.1f ms\n",
           a->mode, b->prim_count, b->node_count, b->leaf_count, b->depth,
           b->prim_count > 0 ? (double)bvh_bytes(b) / b->prim_count : 0.0, a->build_seconds * 1e3);
}

/* Frees the part's state. */
static void cleanup(void *ctx)
{
    Part14 *part = ctx;
    accel_free(&part->accel);
    free(part);
}

static const Program program = {
    .cli = {.part = "1.4-bvh",
            .purpose = "part 1.3's ray tracer, accelerated by bounding boxes and a BVH",
            .options = options,
            .arguments = arguments},
    .features = FEATURE_SPHERES | FEATURE_PLANES | FEATURE_TRIANGLES | FEATURE_POINT_LIGHTS |
                FEATURE_DIRECTIONAL_LIGHTS | FEATURE_AREA_LIGHTS | FEATURE_AMBIENT_LIGHT |
                FEATURE_MIRRORS | FEATURE_SHADING,
    .setup = setup,
    .pixel = trace_pixel,
    .report = report,
    .cleanup = cleanup,
};

/* Renders a scene by the rules of part 1.4. */
int main(int argc, char **argv)
{
    return app_main(&program, argc, argv);
}
