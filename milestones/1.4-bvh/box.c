/* box.c: building axis-aligned boxes, the boxes of spheres and triangles, and the face a ray meets. */
#include "box.h"

#include <math.h>

/* Returns the box that holds nothing: lo = +inf, hi = -inf, so that any union undoes it. */
Box box_empty(void)
{
    return (Box){vec3(INFINITY, INFINITY, INFINITY), vec3(-INFINITY, -INFINITY, -INFINITY)};
}

/* Returns the centre of box b. */
Vec3 box_center(Box b)
{
    return vec3_scale(vec3_add(b.lo, b.hi), 0.5);
}

/* Tells whether box inner lies inside box outer (faces may touch). */
bool box_contains(Box outer, Box inner)
{
    return outer.lo.x <= inner.lo.x && outer.lo.y <= inner.lo.y && outer.lo.z <= inner.lo.z &&
           inner.hi.x <= outer.hi.x && inner.hi.y <= outer.hi.y && inner.hi.z <= outer.hi.z;
}

/* excerpt: box-pad */
/* Returns b grown on every side by 2^-20 of its largest coordinate. The slab test
 * and a surface's own test round differently: a ray through a triangle's corner, which
 * is also its box's corner, might be found by the triangle and missed by the box. The
 * margin, far larger than either rounding error and far smaller than anything seen,
 * makes sure a box never rejects a ray that its surface would accept. */
Box box_pad(Box b)
{
    double m = ldexp(fmax(vec3_max_abs(b.lo), vec3_max_abs(b.hi)), -20);
    return (Box){vec3_sub(b.lo, vec3(m, m, m)), vec3_add(b.hi, vec3(m, m, m))};
}
/* end excerpt: box-pad */

/* starter: todo */
/* excerpt: box-of */
/* Returns the box of sphere s: its centre plus and minus the radius on each axis. */
Box box_of_sphere(const Sphere *s)
{
    Vec3 r = vec3(s->radius, s->radius, s->radius);
    return box_pad((Box){vec3_sub(s->center, r), vec3_add(s->center, r)});
}
/* end excerpt: box-of */

/* starter: todo */
/* excerpt: box-of-triangle */
/* Returns the box of triangle tri: the least and greatest coordinates of its corners. */
Box box_of_triangle(const Triangle *tri)
{
    return box_pad(box_add_point(box_add_point((Box){*tri->a, *tri->a}, *tri->b), *tri->c));
}
/* end excerpt: box-of-triangle */

/* starter: todo */
/* excerpt: box-hit-face */
/* Finds where ray r meets the surface of box b with tmin < t < tmax, and on which face:
 * where it enters the box, or where it leaves it when it starts inside. Modes 1 and 2
 * draw the boxes themselves with this. */
bool box_hit_face(Box b, Ray r, double tmin, double tmax, BoxHit *hit)
{
    /* The slab test again, keeping the axis that set each end of the interval. */
    double lo[3] = {b.lo.x, b.lo.y, b.lo.z}, hi[3] = {b.hi.x, b.hi.y, b.hi.z};
    double o[3] = {r.origin.x, r.origin.y, r.origin.z}, d[3] = {r.dir.x, r.dir.y, r.dir.z};
    double t0 = -INFINITY, t1 = INFINITY;
    int axis0 = 0, axis1 = 0;
    for (int a = 0; a < 3; a++) {
        double near = t0, far = t1;
        box_slab(lo[a], hi[a], o[a], 1 / d[a], &near, &far);
        if (near > t0) {
            t0 = near;
            axis0 = a;
        }
        if (far < t1) {
            t1 = far;
            axis1 = a;
        }
    }
    if (!(t0 <= t1))
        return false;
    double t;
    int axis;
    if (t0 > tmin && t0 < tmax) {
        t = t0;
        axis = axis0;
    } else if (t1 > tmin && t1 < tmax) {
        t = t1;
        axis = axis1;
    } else {
        return false;
    }
    /* The face's normal is +-e_axis; we show the side that faces the ray's origin, so a
     * box seen from inside is lit like one seen from outside. */
    *hit = (BoxHit){t, axis, d[axis] > 0 ? -1 : 1};
    return true;
}
/* end excerpt: box-hit-face */

/* Returns the unit normal of the face of a box hit. */
Vec3 box_face_normal(const BoxHit *hit)
{
    Vec3 n = vec3(0, 0, 0);
    if (hit->axis == 0)
        n.x = hit->sign;
    else if (hit->axis == 1)
        n.y = hit->sign;
    else
        n.z = hit->sign;
    return n;
}
