/* raytra.c: part 1.1: a pixel is red where its primary ray hits a sphere, black elsewhere. */
#include <math.h>
#include <stdlib.h>

#include "app.h"
#include "explain.h"
#include "sphere.h"
#include "view.h"

/* The rule of part 1.1: red where the primary ray hits any sphere at t > 0. */
static Color red_or_black(const void *ctx, int i, int j, RayStats *stats)
{
    const View *view = ctx;
    const Explain *explain = view->opts->explain;
    Ray r = camera_ray(&view->camera, i + 0.5, j + 0.5);
    stats->rays[RAY_PRIMARY]++;
    explain_ray(explain, 0, "camera", r);
    double t;
    for (int k = 0; k < view->scene->sphere_count; k++)
        if (sphere_intersect(&view->scene->spheres[k], r, 0, INFINITY, &t)) {
            char where[300];
            explain_line(explain, 1, "hits sphere %d%s at t = %.9g: red", k,
                         explain_where(explain, view->scene->spheres[k].line, where, sizeof where),
                         t);
            return color(1, 0, 0);
        }
    explain_line(explain, 1, "hits no sphere: black");
    return color(0, 0, 0);
}

/* Tells --view what the camera ray meets first: the nearest sphere, its normal and material. */
static void probe_pixel(const void *ctx, int i, int j, Probe *probe)
{
    const View *view = ctx;
    const Scene *scene = view->scene;
    Ray r = camera_ray(&view->camera, i + 0.5, j + 0.5);
    double t, nearest = INFINITY;
    for (int k = 0; k < scene->sphere_count; k++)
        if (sphere_intersect(&scene->spheres[k], r, 0, nearest, &t)) {
            const Sphere *s = &scene->spheres[k];
            Vec3 n = vec3_scale(vec3_sub(ray_at(r, t), s->center), 1 / s->radius);
            nearest = t;
            *probe = (Probe){.hit = true,
                             .t = t,
                             .surface = k,
                             .normal = vec3_dot(n, r.dir) > 0 ? vec3_neg(n) : n,
                             .kd = scene->materials[s->material].diffuse};
        }
}

static const Program program = {
    .cli = {.part = "1.1-spheres-red",
            .purpose = "a pixel is red where its primary ray hits a sphere, black elsewhere"},
    .features = FEATURE_SPHERES,
    .setup = view_setup,
    .pixel = red_or_black,
    .probe = probe_pixel,
    .cleanup = free,
};

/* Renders a scene by the rule of part 1.1. */
int main(int argc, char **argv)
{
    return app_main(&program, argc, argv);
}
