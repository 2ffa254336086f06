/* box.c: making boxes, the boxes of spheres and triangles, and the face of a box a ray meets. */
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

/* Returns the box of surface s of scene (a number of world_intersect): its sphere's or
 * its triangle's; a plane's is all of space, which every ray meets. */
Box box_of_surface(const Scene *scene, int s)
{
    int planes = scene->sphere_count + scene->plane_count;
    if (s < scene->sphere_count)
        return box_of_sphere(&scene->spheres[s]);
    if (s < planes)
        return (Box){vec3(-INFINITY, -INFINITY, -INFINITY), vec3(INFINITY, INFINITY, INFINITY)};
    Triangle tri = scene_triangle(scene, s - planes);
    return box_of_triangle(&tri);
}

/* starter: todo */
/* Returns the box of sphere s: its centre plus and minus the radius on each axis, grown
 * by box_pad (2^-20 of its largest coordinate, on every side), as every surface's box
 * is. tests/test_box.c: boxes_of_surfaces. */
Box box_of_sphere(const Sphere *s)
{
    Vec3 r = vec3(s->radius, s->radius, s->radius);
    return box_pad((Box){vec3_sub(s->center, r), vec3_add(s->center, r)});
}

/* starter: todo */
/* Returns the box of triangle tri: the least and greatest coordinates of its three
 * corners on each axis, grown by box_pad (2^-20 of its largest coordinate, on every
 * side), as every surface's box is. tests/test_box.c: boxes_of_surfaces. */
Box box_of_triangle(const Triangle *tri)
{
    return box_pad(box_add_point(box_add_point((Box){*tri->a, *tri->a}, *tri->b), *tri->c));
}

/* starter: todo */
/* Finds where ray r meets the surface of the closed box b with tmin < t < tmax (strict,
 * as every surface's test), and the unit normal of the face there: where it enters
 * the box (the slab test's t0, from box_slab, which swaps the planes for a negative
 * direction), or where it leaves it (t1) when t0 is not in (tmin, tmax). The normal is
 * +-e_axis of the face's axis, facing the ray's origin: -sign(d) on that axis. At an
 * edge or a corner, where faces of two axes give the same t, the lower axis (x, y, z)
 * is the face. Modes 1 and 2 draw the boxes themselves with this. tests/test_box.c:
 * faces_of_boxes and the others that call box_hit_face. */
bool box_hit_face(Box b, Ray r, double tmin, double tmax, double *t, Vec3 *normal)
{
    /* The slab test again, keeping the axis that set each end of the interval. */
    double t0 = -INFINITY, t1 = INFINITY;
    int axis0 = 0, axis1 = 0;
    for (int a = 0; a < 3; a++) {
        double near = t0, far = t1;
        box_slab(vec3_axis(b.lo, a), vec3_axis(b.hi, a), vec3_axis(r.origin, a),
                 1 / vec3_axis(r.dir, a), &near, &far);
        if (near > t0) {
            t0 = near;
            axis0 = a;
        }
        if (far < t1) {
            t1 = far;
            axis1 = a;
        }
    }
    bool enters = t0 > tmin && t0 < tmax;
    int axis = enters ? axis0 : axis1;
    *t = enters ? t0 : t1;
    if (!(t0 <= t1 && *t > tmin && *t < tmax))
        return false;
    /* +-e_axis, the side facing the ray's origin: a box seen from inside is lit as from outside. */
    double side = vec3_axis(r.dir, axis) > 0 ? -1 : 1;
    *normal = vec3(axis == 0 ? side : 0, axis == 1 ? side : 0, axis == 2 ? side : 0);
    return true;
}
