/* raytra.c: part 1.2: the closest hit, shaded by Blinn-Phong under every light; no shadows. */
#include <math.h>
#include <stdlib.h>

#include "app.h"
#include "shade.h"
#include "view.h"
#include "world.h"

/* excerpt: shade-pixel */
/* Part 1.2's pixel: the surface nearest the eye, lit by every light; black where the ray
 * meets nothing. */
static Color shade_pixel(const void *ctx, int i, int j, RayStats *stats)
{
    const View *view = ctx;
    Ray r = camera_ray(&view->camera, i + 0.5, j + 0.5);
    stats->rays[RAY_PRIMARY]++;
    Hit hit;
    if (!world_hit(view->scene, r, 0, INFINITY, &hit))
        return color(0, 0, 0);
    return shade_direct_radiance(view->scene, &hit, r, view->opts->two_sided);
}
/* end excerpt: shade-pixel */

/* Builds the view, saying first how area lights are lit in this part. */
static bool setup(const Scene *scene, const Options *opts, void **ctx)
{
    light_note_area_lights(scene);
    return view_setup(scene, opts, ctx);
}

static const Program program = {
    .cli = {.part = "1.2-shading",
            .purpose = "the nearest surface of each pixel, lit by Blinn-Phong shading"},
    .features = FEATURE_SPHERES | FEATURE_PLANES | FEATURE_TRIANGLES | FEATURE_POINT_LIGHTS |
                FEATURE_DIRECTIONAL_LIGHTS | FEATURE_AREA_LIGHTS | FEATURE_SHADING,
    .setup = setup,
    .pixel = shade_pixel,
    .cleanup = free,
};

/* Renders a scene by the rules of part 1.2. */
int main(int argc, char **argv)
{
    return app_main(&program, argc, argv);
}
