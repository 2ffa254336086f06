/* sphere.c: the ray-sphere intersection, computed without cancellation.
 * Slides 51-53 ("spheres - intersections"). */
#include "sphere.h"

#include <math.h>

/* starter: todo */
/* excerpt: sphere-intersect */
/* Finds the nearest t with tmin < t < tmax where ray r meets sphere s. */
bool sphere_intersect(const Sphere *s, Ray r, double tmin, double tmax, double *t)
{
    /* Putting r(t) = p0 + t d into (p - O).(p - O) - R^2 = 0 gives the quadratic
     * a t^2 + 2 b t + c = 0 with a = d.d, b = d.(p0 - O), c = (p0 - O).(p0 - O) - R^2. */
    Vec3 f = vec3_sub(r.origin, s->center);
    double a = vec3_dot(r.dir, r.dir);
    double b = vec3_dot(r.dir, f);
    double c = vec3_dot(f, f) - s->radius * s->radius;

    /* excerpt: sphere-discriminant */
    /* The discriminant b^2 - a c equals a (R^2 - |f - (b/a) d|^2), where f - (b/a) d
     * joins the centre to the point of the line nearest to it. This form never
     * subtracts two large, nearly equal numbers, so far-away spheres stay round. */
    Vec3 nearest = vec3_add_scaled(f, r.dir, -b / a);
    double discriminant = a * (s->radius * s->radius - vec3_dot(nearest, nearest));
    if (discriminant < 0)
        return false; /* the line passes the sphere by */
    /* end excerpt: sphere-discriminant */

    /* excerpt: sphere-roots */
    /* The roots (-b +- sqrt(disc)) / a. Computing q = -(b + sign(b) sqrt(disc)) adds
     * numbers of the same sign, and the roots are q / a and c / q (their product is c / a). */
    double q = -(b + copysign(sqrt(discriminant), b));
    double t0 = q / a;
    double t1 = q != 0 ? c / q : t0; /* q = 0 only for a graze at t = 0 */
    if (t0 > t1) {
        double swap = t0;
        t0 = t1;
        t1 = swap;
    }
    /* The nearer root first; the farther one when the ray starts inside the sphere. */
    if (t0 > tmin && t0 < tmax) {
        *t = t0;
        return true;
    }
    if (t1 > tmin && t1 < tmax) {
        *t = t1;
        return true;
    }
    return false;
    /* end excerpt: sphere-roots */
}
/* end excerpt: sphere-intersect */
