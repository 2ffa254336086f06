/* secondary.h: rays that leave a surface: the reflected direction, and where such rays start. */
#ifndef RAYTRA_SECONDARY_H
#define RAYTRA_SECONDARY_H

#include "hit.h"
#include "ray.h"

/* The default of --ray-offset: 2^-32, about a million times double precision's rounding. */
#define SECONDARY_OFFSET 0x1p-32

Ray secondary_ray(const Hit *hit, Ray incoming, Vec3 dir, double offset);
Vec3 secondary_reflect(Vec3 d, Vec3 n);

#endif
