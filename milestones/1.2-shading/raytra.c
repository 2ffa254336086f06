/* raytra.c: part 1.2: the closest hit, shaded by Blinn-Phong under every light; no shadows. */
#include <math.h>
#include <stdlib.h>

#include "app.h"
#include "shade.h"
#include "view.h"
#include "world.h"

/* What every pixel reads: the camera and the scene, and --two-sided, read once. */
typedef struct {
    View view;
    bool two_sided;
} Part12;

/* Builds the camera of the scene and reads --two-sided. */
static bool setup(const Scene *scene, const Options *opts, void **ctx)
{
    Part12 *part = malloc(sizeof *part);
    if (part == NULL)
        return false;
    *part = (Part12){.view = {camera_make(&scene->camera), scene, opts},
                     .two_sided = cli_flag(opts, "two-sided")};
    *ctx = part;
    return true;
}

/* Part 1.2's pixel: the surface nearest the eye, lit by every light; black where the ray
 * meets nothing. */
static Color shade_pixel(const void *ctx, int i, int j, RayStats *stats)
{
    const Part12 *part = ctx;
    const View *view = &part->view;
    const Explain *explain = view->opts->explain;
    Ray r = camera_ray(&view->camera, i + 0.5, j + 0.5);
    stats->rays[RAY_PRIMARY]++;
    explain_ray(explain, 0, "camera", r);
    Hit hit;
    if (!world_hit(view->scene, r, 0, INFINITY, &hit)) {
        explain_line(explain, 1, "hits nothing: the black background");
        return color(0, 0, 0);
    }
    world_explain_hit(explain, 1, &hit);
    shade_explain_lights(explain, view->scene, &hit, r, part->two_sided);
    return shade_direct_radiance(view->scene, &hit, r, part->two_sided);
}

/* Tells --view what the camera ray meets first, and how many lights face the point. */
static void probe_pixel(const void *ctx, int i, int j, Probe *probe)
{
    const Part12 *part = ctx;
    const View *view = &part->view;
    const Scene *scene = view->scene;
    Ray r = camera_ray(&view->camera, i + 0.5, j + 0.5);
    Hit hit;
    if (!world_hit(scene, r, 0, INFINITY, &hit))
        return;
    Vec3 n = shade_normal(&hit);
    *probe = (Probe){.hit = true,
                     .t = hit.t,
                     .normal = n,
                     .surface = world_surface_id(scene, &hit),
                     .kd = shade_material(scene, &hit, part->two_sided)->diffuse};
    for (int k = 0; k < scene->light_count; k++) {
        Incident in = light_incident(&scene->lights[k], hit.point, false);
        probe->lights_visible += scene->lights[k].kind != LIGHT_AREA && vec3_dot(n, in.dir) > 0;
    }
}

static const Program program = {
    .cli = {.part = "1.2-shading",
            .options = shade_part_options,
            .purpose = "the nearest surface of each pixel, lit by Blinn-Phong shading"},
    .features = FEATURE_SPHERES | FEATURE_PLANES | FEATURE_TRIANGLES | FEATURE_POINT_LIGHTS |
                FEATURE_DIRECTIONAL_LIGHTS | FEATURE_SHADING,
    .setup = setup,
    .pixel = shade_pixel,
    .probe = probe_pixel,
    .views = 1u << VIEW_LIGHT_COUNT,
    .cleanup = free,
};

/* Renders a scene by the rules of part 1.2. */
int main(int argc, char **argv)
{
    return app_main(&program, argc, argv);
}
