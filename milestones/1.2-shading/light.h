/* light.h: what reaches a point from a light: from which direction, how far, how much. */
#ifndef RAYTRA_LIGHT_H
#define RAYTRA_LIGHT_H

#include <stdbool.h>

#include "color.h"
#include "scene.h"

/* The light arriving at a point from one light. */
typedef struct {
    Vec3 dir;        /* unit vector from the point towards the light: l */
    double distance; /* how far away the light is; INFINITY for a directional light */
    Color radiance;  /* I: the light's colour, divided by distance^2 when it falls off */
} Incident;

Incident light_incident(const Light *light, Vec3 point, bool falls_off);

#endif
