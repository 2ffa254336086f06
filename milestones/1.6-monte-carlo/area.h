/* area.h: the square area light `l s`: points on it, and the light each sends to a surface. */
#ifndef RAYTRA_AREA_H
#define RAYTRA_AREA_H

#include <stdbool.h>

#include "light.h"
#include "scene.h"

Vec3 area_point(const Light *light, double ru, double rv);
Incident area_incident(const Light *light, Vec3 at, Vec3 point, int count, bool falls_off);

#endif
