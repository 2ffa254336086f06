/* triangle.c: the barycentric ray-triangle test of the textbook (section 4.4.2), by Cramer's rule.
 */
#include "triangle.h"

/* starter: todo */
/* Finds t with tmin < t < tmax where ray r meets triangle tri, from either side, and
 * the barycentric coordinates of the point; edges and corners count as inside. */
bool triangle_intersect(const Triangle *tri, Ray r, double tmin, double tmax, TriangleHit *hit)
{
    /* A point of the triangle's plane is a + beta e1 + gamma e2 with e1 = b - a and
     * e2 = c - a. The ray meets it where p0 + t d = a + beta e1 + gamma e2, that is
     *     beta e1 + gamma e2 - t d = s,   with s = p0 - a:
     * three equations (x, y, z) in three unknowns. Cramer's rule solves them as
     * ratios of determinants, and a 3 x 3 determinant det[x y z] is the triple
     * product x . (y x z): the textbook's formulas, written with vectors. */
    Vec3 e1 = vec3_sub(*tri->b, *tri->a);
    Vec3 e2 = vec3_sub(*tri->c, *tri->a);
    Vec3 s = vec3_sub(r.origin, *tri->a);
    Vec3 p = vec3_cross(r.dir, e2);
    double det = vec3_dot(e1, p); /* det[e1 e2 -d] */
    /* Zero: the ray is parallel to the plane, or the triangle has no area. */
    if (det == 0)
        return false;
    double beta = vec3_dot(s, p) / det;
    if (!(beta >= 0 && beta <= 1))
        return false;
    Vec3 q = vec3_cross(s, e1);
    double gamma = vec3_dot(r.dir, q) / det;
    if (!(gamma >= 0 && beta + gamma <= 1))
        return false;
    double t = vec3_dot(e2, q) / det;
    if (!(t > tmin && t < tmax))
        return false;
    *hit = (TriangleHit){t, beta, gamma};
    return true;
}

/* Returns the unit normal (b - a) x (c - a): it points towards whoever sees a, b, c
 * counterclockwise, the front side. */
Vec3 triangle_normal(const Triangle *tri)
{
    return vec3_normalize(vec3_cross(vec3_sub(*tri->b, *tri->a), vec3_sub(*tri->c, *tri->a)));
}
