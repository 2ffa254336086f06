/* area.c: a square area light as many small point lights, each 1/N of it (the assignment's M6). */
#include "area.h"

/* starter: todo */
/* Returns the point (ru, rv) in [0,1)^2 of the square light: its centre plus (ru - 1/2)
 * sides along u and (rv - 1/2) sides along v = u x n, the assignment's
 * "XYZ + (ru - .5)*U*len + (rv - .5)*V*len". */
Vec3 area_point(const Light *light, double ru, double rv)
{
    Vec3 p = vec3_add_scaled(light->position, light->u, (ru - 0.5) * light->size);
    return vec3_add_scaled(p, light->v, (rv - 0.5) * light->size);
}

/* starter: todo */
/* Returns what reaches point from the spot at of the light when count shadow rays share
 * it: a point light at that spot with 1/count of the light's colour ("each shadow ray
 * represents 1/N times the light's radiant exitance"), falling off as 1/r^2 when
 * falls_off. The square emits only on the side its normal n faces ("pointing in
 * direction n"): a point behind its plane, or in it, receives nothing. */
Incident area_incident(const Light *light, Vec3 at, Vec3 point, int count, bool falls_off)
{
    Light spot = {.kind = LIGHT_POINT, .position = at,
                  .color = color_scale(light->color, 1.0 / count)};
    Incident in = light_incident(&spot, point, falls_off);
    if (!(vec3_dot(vec3_sub(point, at), light->direction) > 0))
        in.radiance = color(0, 0, 0);
    return in;
}
