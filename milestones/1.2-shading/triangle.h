/* triangle.h: where a ray meets a triangle, with the barycentric coordinates of the hit. */
#ifndef RAYTRA_TRIANGLE_H
#define RAYTRA_TRIANGLE_H

#include <stdbool.h>

#include "ray.h"
#include "scene.h"

/* Where a ray meets a triangle: p = a + beta (b - a) + gamma (c - a) = r(t). */
typedef struct {
    double t, beta, gamma;
} TriangleHit;

bool triangle_intersect(const Triangle *tri, Ray r, double tmin, double tmax, TriangleHit *hit);
Vec3 triangle_normal(const Triangle *tri);

#endif
