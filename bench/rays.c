/* rays.c: the benchmark's sets of rays: a pinhole camera's primary rays, and shadow rays. */
#include "rays.h"

#include <math.h>
#include <stdlib.h>

#include "world.h"

/* The primary rays of a pinhole camera at eye looking along view, n x n of them over a
 * square field of view of fov radians; y is up. */
BenchRay *rays_primary(Vec3 eye, Vec3 view, double fov, int n)
{
    BenchRay *rays = malloc((size_t)n * n * sizeof *rays);
    Vec3 w = vec3_normalize(view);
    Vec3 u = vec3_normalize(vec3_cross(w, vec3(0, 1, 0))), v = vec3_cross(u, w);
    double half = tan(fov / 2);
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            double x = ((i + 0.5) / n * 2 - 1) * half, y = ((j + 0.5) / n * 2 - 1) * half;
            Vec3 d = vec3_normalize(vec3_add(w, vec3_add(vec3_scale(u, x), vec3_scale(v, y))));
            rays[(size_t)j * n + i] = (BenchRay){ray(eye, d), INFINITY};
        }
    return rays;
}

/* The shadow rays from the hits of the primary rays towards a point light: from the hit
 * point, moved off the surface by 1e-6 of the scene's size, to the light. */
BenchRay *rays_shadow(const Bvh *bvh, const BenchRay *primary, long n, Vec3 light, double size,
                      long *count)
{
    BenchRay *rays = malloc((size_t)n * sizeof *rays);
    long m = 0;
    for (long k = 0; k < n; k++) {
        Hit hit;
        long tests = 0;
        if (!bvh_hit(bvh, primary[k].ray, 0, INFINITY, &hit, &tests))
            continue;
        world_complete_hit(bvh->scene, primary[k].ray, &hit);
        Vec3 side = hit.back_face ? vec3_neg(hit.normal) : hit.normal;
        Vec3 p = vec3_add_scaled(hit.point, side, 1e-6 * size);
        Vec3 to = vec3_sub(light, p);
        double d = vec3_length(to);
        rays[m++] = (BenchRay){ray(p, vec3_scale(to, 1 / d)), d};
    }
    *count = m;
    return rays;
}
