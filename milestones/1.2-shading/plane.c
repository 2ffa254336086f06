/* plane.c: the ray-plane intersection of slide 47 ("ray-plane intersection"). */
#include "plane.h"

/* starter: todo */
/* Finds t with tmin < t < tmax where ray r meets plane pl, from either side. */
bool plane_intersect(const Plane *pl, Ray r, double tmin, double tmax, double *t)
{
    /* Putting r(t) = p0 + t d into p.N + d = 0 gives (p0 + t d).N + d = 0, so
     * t = -(p0.N + d) / (d.N). When d.N = 0 the ray runs parallel to the plane. */
    double denominator = vec3_dot(r.dir, pl->normal);
    if (denominator == 0)
        return false;
    double root = -(vec3_dot(r.origin, pl->normal) + pl->d) / denominator;
    if (!(root > tmin && root < tmax))
        return false;
    *t = root;
    return true;
}
