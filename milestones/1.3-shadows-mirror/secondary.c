/* secondary.c: starting shadow and reflected rays just off the surface, on the side they leave by.
 */
#include "secondary.h"

/* excerpt: secondary-ray */
/* Returns the ray along unit dir from hit's point, started a little off the surface on
 * the side dir leaves by, so that it does not find the surface it starts from.
 *
 * The hit point is computed in floating point, so it lies a tiny distance before or
 * behind the true surface, and a ray started there may hit the surface itself at a
 * t close to 0: "shadow acne". Rounding errors are relative to the size of the
 * numbers, so the offset is too: offset times the largest coordinate of the hit point
 * or of the ray's origin. The default, 2^-32, is about a million times the rounding
 * error of a double, and still a ten-billionth of the scene's size: no contact point
 * or thin wall is visibly affected, whatever the scene's scale. */
Ray secondary_ray(const Hit *hit, Ray incoming, Vec3 dir, double offset)
{
    double scale = fmax(vec3_max_abs(hit->point), vec3_max_abs(incoming.origin));
    double distance = offset * fmax(scale, 1e-300);
    if (vec3_dot(dir, hit->normal) < 0)
        distance = -distance;
    return ray(vec3_add_scaled(hit->point, hit->normal, distance), dir);
}
/* end excerpt: secondary-ray */

/* excerpt: secondary-reflect */
/* Returns the mirror image of direction d about the normal n (unit): r = d - 2 (d.n) n.
 * The part of d along n changes sign; the part along the surface stays. */
Vec3 secondary_reflect(Vec3 d, Vec3 n)
{
    return vec3_add_scaled(d, n, -2 * vec3_dot(d, n));
}
/* end excerpt: secondary-reflect */
