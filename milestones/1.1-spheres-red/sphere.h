/* sphere.h: where a ray meets a sphere. */
#ifndef RAYTRA_SPHERE_H
#define RAYTRA_SPHERE_H

#include <stdbool.h>

#include "ray.h"
#include "scene.h"

bool sphere_intersect(const Sphere *s, Ray r, double tmin, double tmax, double *t);

#endif
