/* ray.h: the ray r(t) = origin + t dir, the one thing every part traces. */
#ifndef RAYTRA_RAY_H
#define RAYTRA_RAY_H

#include "vec3.h"

typedef struct {
    Vec3 origin;
    Vec3 dir; /* unit length wherever raytra makes a ray */
} Ray;

/* Returns the point r(t) = origin + t dir. */
static inline Vec3 ray_at(Ray r, double t)
{
    return vec3_add_scaled(r.origin, r.dir, t);
}

/* Returns the ray from origin along dir. */
static inline Ray ray(Vec3 origin, Vec3 dir)
{
    return (Ray){origin, dir};
}

#endif
