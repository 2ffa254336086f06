/* light.c: point and directional lights as seen from a surface point. */
#include "light.h"

#include <math.h>

/* starter: todo */
/* Returns what reaches point from light; falls_off says whether point lights fade as 1/r^2. */
Incident light_incident(const Light *light, Vec3 point, bool falls_off)
{
    Incident in = {.radiance = light->color};
    if (light->kind == LIGHT_DIRECTIONAL) {
        /* `l d v` shines along v: its light arrives from -v, from infinitely far. */
        in.dir = vec3_neg(light->direction);
        in.distance = INFINITY;
        return in;
    }
    /* A point light (part 1.6 makes each sample of an area light one). */
    Vec3 to_light = vec3_sub(light->position, point);
    in.distance = vec3_length(to_light);
    if (in.distance == 0) {
        /* A light exactly at the point has no direction: it lights nothing here. */
        in.dir = vec3(0, 0, 0);
        in.radiance = color(0, 0, 0);
        return in;
    }
    in.dir = vec3_scale(to_light, 1 / in.distance);
    /* 1/r^2, kept finite for a light within a millionth of a unit of the point. */
    if (falls_off)
        in.radiance = color_scale(in.radiance, 1 / fmax(in.distance * in.distance, 1e-12));
    return in;
}
