/* box.h: axis-aligned bounding boxes, their slab test, and the boxes of spheres and triangles. */
#ifndef RAYTRA_BOX_H
#define RAYTRA_BOX_H

#include <stdbool.h>

#include "ray.h"
#include "scene.h"

/* The points p with lo <= p <= hi in every coordinate: two corners, as the textbook keeps it. */
typedef struct {
    Vec3 lo, hi;
} Box;

/* A ray made ready for slab tests: 1/d once per ray, not once per box (1/+-0 = +-inf). */
typedef struct {
    Vec3 origin;
    Vec3 inv_dir;
} BoxRay;

/* Returns the ray r made ready for box_hit. */
static inline BoxRay box_ray(Ray r)
{
    return (BoxRay){r.origin, vec3(1 / r.dir.x, 1 / r.dir.y, 1 / r.dir.z)};
}

/* Narrows [*t0, *t1] to the t where the ray lies between the planes x_axis = lo and
 * x_axis = hi (the textbook's slab test): it enters at the nearer plane, hi first when
 * it travels towards -x. Parallel to the slab, (lo - o) * inf is +-inf: no constraint,
 * or an empty interval. On a plane of the slab, 0 * inf = NaN, which every comparison
 * below rejects: the plane counts as part of the box, which is closed. */
static inline void box_slab(double lo, double hi, double o, double inv, double *t0, double *t1)
{
    double near = (lo - o) * inv, far = (hi - o) * inv;
    if (inv < 0) {
        double swap = near;
        near = far;
        far = swap;
    }
    if (near > *t0)
        *t0 = near;
    if (far < *t1)
        *t1 = far;
}

/* Tells whether ray r meets box b at some t with tmin <= t <= tmax: the three slabs'
 * intervals and [tmin, tmax] overlap. Sets *t_enter to where the overlap begins. */
static inline bool box_hit(Box b, const BoxRay *r, double tmin, double tmax, double *t_enter)
{
    box_slab(b.lo.x, b.hi.x, r->origin.x, r->inv_dir.x, &tmin, &tmax);
    box_slab(b.lo.y, b.hi.y, r->origin.y, r->inv_dir.y, &tmin, &tmax);
    box_slab(b.lo.z, b.hi.z, r->origin.z, r->inv_dir.z, &tmin, &tmax);
    *t_enter = tmin;
    return tmin <= tmax;
}

/* Returns the smallest box holding a and b. */
static inline Box box_union(Box a, Box b)
{
    return (Box){vec3_min(a.lo, b.lo), vec3_max(a.hi, b.hi)};
}

/* Returns the smallest box holding b and the point p. */
static inline Box box_add_point(Box b, Vec3 p)
{
    return box_union(b, (Box){p, p});
}

/* Returns half the surface area of box b, the quantity the SAH compares (0 when empty). */
static inline double box_half_area(Box b)
{
    Vec3 e = vec3_sub(b.hi, b.lo);
    if (!(e.x >= 0 && e.y >= 0 && e.z >= 0))
        return 0;
    return e.x * e.y + e.y * e.z + e.z * e.x;
}

Box box_empty(void);
Vec3 box_center(Box b);
Box box_pad(Box b);
Box box_of_surface(const Scene *scene, int s);
Box box_of_sphere(const Sphere *s);
Box box_of_triangle(const Triangle *tri);
bool box_hit_face(Box b, Ray r, double tmin, double tmax, double *t, Vec3 *normal);

#endif
