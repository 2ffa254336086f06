/* rays.h: the benchmark's sets of rays: a pinhole camera's primary rays, and shadow rays. */
#ifndef RAYTRA_RAYS_H
#define RAYTRA_RAYS_H

#include "baseline.h"
#include "bvh.h"

BenchRay *rays_primary(Vec3 eye, Vec3 view, double fov, int n);
BenchRay *rays_shadow(const Bvh *bvh, const BenchRay *primary, long n, Vec3 light, double size,
                      long *count);

#endif
