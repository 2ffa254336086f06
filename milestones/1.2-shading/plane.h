/* plane.h: where a ray meets a plane. */
#ifndef RAYTRA_PLANE_H
#define RAYTRA_PLANE_H

#include <stdbool.h>

#include "ray.h"
#include "scene.h"

bool plane_intersect(const Plane *pl, Ray r, double tmin, double tmax, double *t);

#endif
