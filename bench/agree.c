/* agree.c: why tinybvh counts other hits than raytra: the rays the two disagree on, one by one. */
#include "agree.h"

#include <math.h>

/* Returns the determinant e1 . (d x e2) of tinybvh's Moller-Trumbore test of ray r
 * against triangle number k, in float as tinybvh works it out: twice the triangle's area
 * times the cosine of the angle between the ray and the triangle's normal. */
static float tiny_determinant(const Scene *scene, int k, Ray r)
{
    float v[3][3], d[3];
    for (int c = 0; c < 3; c++) {
        Vec3 p = scene->vertices[scene->triangles[k].corner[c]];
        v[c][0] = (float)p.x, v[c][1] = (float)p.y, v[c][2] = (float)p.z;
    }
    d[0] = (float)r.dir.x, d[1] = (float)r.dir.y, d[2] = (float)r.dir.z;
    float len = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    float e1[3], e2[3];
    for (int a = 0; a < 3; a++) {
        d[a] /= len;
        e1[a] = v[1][a] - v[0][a];
        e2[a] = v[2][a] - v[0][a];
    }
    float h[3] = {d[1] * e2[2] - d[2] * e2[1], d[2] * e2[0] - d[0] * e2[2],
                  d[0] * e2[1] - d[1] * e2[0]};
    return e1[0] * h[0] + e1[1] * h[1] + e1[2] * h[2];
}

/* Traces each of rays[0 .. n) with raytra's BVH and with tiny, closest hits or shadow
 * rays, and counts the rays they answer differently; for a ray raytra hits and tiny
 * does not, tells whether raytra's first triangle along it is one tinybvh calls
 * parallel. */
Disagreement agree_tiny(const Bvh *bvh, const TinyBaseline *tiny, const BenchRay *rays, long n,
                        bool shadow)
{
    Disagreement d = {0};
    for (long k = 0; k < n; k++) {
        const BenchRay *br = &rays[k];
        Hit hit;
        long tests = 0;
        bool mine = shadow ? bvh_blocked(bvh, br->ray, 0, br->tmax)
                           : bvh_hit(bvh, br->ray, 0, br->tmax, &hit, &tests);
        bool theirs = tiny_trace(tiny, rays, k, k + 1, shadow) > 0;
        if (mine == theirs)
            continue;
        if (!mine) {
            d.extra++;
            continue;
        }
        d.missed++;
        if (shadow)
            bvh_hit(bvh, br->ray, 0, br->tmax, &hit, &tests);
        if (fabsf(tiny_determinant(bvh->scene, hit.index, br->ray)) < TINY_PARALLEL)
            d.flat++;
    }
    return d;
}
