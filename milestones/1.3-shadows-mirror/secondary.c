/* secondary.c: starting shadow and reflected rays just off the surface, on the side they leave by.
 */
#include "secondary.h"

/* starter: todo */
/* Returns the ray along unit dir from hit's point, started off the surface on the side
 * dir leaves by, so that it cannot find the surface it starts from (shadow acne): by
 * offset times the largest coordinate of the point or of the ray's origin, since
 * rounding errors grow with the numbers. */
Ray secondary_ray(const Hit *hit, Ray incoming, Vec3 dir, double offset)
{
    double scale = fmax(vec3_max_abs(hit->point), vec3_max_abs(incoming.origin));
    double distance = offset * fmax(scale, 1e-300);
    if (vec3_dot(dir, hit->normal) < 0)
        distance = -distance;
    return ray(vec3_add_scaled(hit->point, hit->normal, distance), dir);
}

/* starter: todo */
/* Returns the mirror image of direction d about the normal n (unit): r = d - 2 (d.n) n.
 * The part of d along n changes sign; the part along the surface stays. */
Vec3 secondary_reflect(Vec3 d, Vec3 n)
{
    return vec3_add_scaled(d, n, -2 * vec3_dot(d, n));
}
