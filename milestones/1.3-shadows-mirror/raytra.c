/* raytra.c: part 1.3: shadows, ambient light and mirror reflection, by recursive ray tracing. */
#include <math.h>
#include <stdlib.h>

#include "app.h"
#include "light.h"
#include "secondary.h"
#include "trace.h"
#include "view.h"

static int max_depth = TRACE_MAX_DEPTH;
static bool two_sided;
static double offset = SECONDARY_OFFSET;

static const CliOption options[] = {
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

/* What every pixel reads: the camera, and the tracer with its scene and settings. */
typedef struct {
    View view;
    Tracer tracer;
} Part13;

/* Builds the camera and the tracer of the scene. */
static bool setup(const Scene *scene, void **ctx)
{
    Part13 *part = malloc(sizeof *part);
    if (part == NULL)
        return false;
    light_note_area_lights(scene);
    part->view = (View){camera_make(&scene->camera), scene};
    part->tracer = (Tracer){.scene = scene,
                            .surfaces = surfaces_brute_force(scene),
                            .max_depth = max_depth,
                            .two_sided = two_sided,
                            .offset = offset};
    *ctx = part;
    return true;
}

/* excerpt: trace-pixel */
/* Part 1.3's pixel: the radiance along the primary ray through its centre. */
static Color trace_pixel(const void *ctx, int i, int j, RayStats *stats)
{
    const Part13 *part = ctx;
    Ray r = camera_ray(&part->view.camera, i + 0.5, j + 0.5);
    stats->rays[RAY_PRIMARY]++;
    return trace_radiance(&part->tracer, r, 0, stats);
}
/* end excerpt: trace-pixel */

static const Program program = {
    .cli = {.part = "1.3-shadows-mirror",
            .purpose = "Blinn-Phong shading with shadows, ambient light and mirror reflection",
            .options = options},
    .features = FEATURE_SPHERES | FEATURE_PLANES | FEATURE_TRIANGLES | FEATURE_POINT_LIGHTS |
                FEATURE_DIRECTIONAL_LIGHTS | FEATURE_AREA_LIGHTS | FEATURE_AMBIENT_LIGHT |
                FEATURE_MIRRORS | FEATURE_SHADING,
    .setup = setup,
    .pixel = trace_pixel,
    .cleanup = free,
};

/* Renders a scene by the rules of part 1.3. */
int main(int argc, char **argv)
{
    return app_main(&program, argc, argv);
}
