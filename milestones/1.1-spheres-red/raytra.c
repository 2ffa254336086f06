/* raytra.c: part 1.1: a pixel is red where its primary ray hits a sphere, black elsewhere. */
#include <math.h>
#include <stdlib.h>

#include "app.h"
#include "sphere.h"
#include "view.h"

/* excerpt: red-or-black */
/* The rule of part 1.1: red where the primary ray hits any sphere at t > 0. */
static Color red_or_black(const void *ctx, int i, int j, RayStats *stats)
{
    const View *view = ctx;
    Ray r = camera_ray(&view->camera, i + 0.5, j + 0.5);
    stats->rays[RAY_PRIMARY]++;
    double t;
    for (int k = 0; k < view->scene->sphere_count; k++)
        if (sphere_intersect(&view->scene->spheres[k], r, 0, INFINITY, &t))
            return color(1, 0, 0);
    return color(0, 0, 0);
}
/* end excerpt: red-or-black */

static const Program program = {
    .cli = {.part = "1.1-spheres-red",
            .purpose = "a pixel is red where its primary ray hits a sphere, black elsewhere"},
    .features = FEATURE_SPHERES,
    .setup = view_setup,
    .pixel = red_or_black,
    .cleanup = free,
};

/* Renders a scene by the rule of part 1.1. */
int main(int argc, char **argv)
{
    return app_main(&program, argc, argv);
}
