/* accel.c: Surfaces for the course's modes: boxes as rejection tests, boxes drawn, and the BVH. */
#include "accel.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "plane.h"
#include "sphere.h"
#include "triangle.h"
#include "world.h"

/* Returns the seconds of a monotonic clock. */
static double seconds_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* Builds what mode needs for scene: the surfaces' boxes or the BVH; false (reported, with
 * nothing left to free) when out of memory. */
bool accel_build(Accel *accel, const Scene *scene, AccelMode mode)
{
    double start = seconds_now();
    *accel = (Accel){.mode = mode, .scene = scene};
    bool ok = true;
    if (mode == ACCEL_BOXED || mode == ACCEL_SURFACE_BOXES) {
        int n = scene->sphere_count + scene->triangle_count;
        accel->boxes = malloc((size_t)(n > 0 ? n : 1) * sizeof *accel->boxes);
        ok = accel->boxes != NULL;
        for (int k = 0; ok && k < n; k++)
            accel->boxes[k] = bvh_prim_box(scene, (uint32_t)k);
    } else {
        ok = bvh_build(&accel->bvh, scene);
    }
    accel->build_seconds = seconds_now() - start;
    if (!ok) {
        fprintf(stderr, "raytra: not enough memory for the bounding boxes of %s\n", scene->path);
        accel_free(accel);
    }
    return ok;
}

/* Frees what accel_build allocated. */
void accel_free(Accel *accel)
{
    free(accel->boxes);
    bvh_free(&accel->bvh);
}

/* Tells whether a hit at t on surface (kind, index) beats best: nearer, or as near and
 * tested first by part 1.2's world_hit (spheres, planes, triangles, each in order). */
static bool beats(double t, SurfaceKind kind, int index, bool found, const Hit *best)
{
    if (!found || t < best->t)
        return true;
    return t == best->t && (kind < best->kind || (kind == best->kind && index < best->index));
}

/* Offers every plane to the closest hit so far: planes have no box and are not in any
 * hierarchy. Hits at exactly best->t are tested too, for the order of ties. */
static bool planes_hit(const Scene *scene, Ray r, double tmin, double tmax, bool found, Hit *best)
{
    for (int k = 0; k < scene->plane_count; k++) {
        double t, limit = found ? nextafter(best->t, INFINITY) : tmax;
        if (plane_intersect(&scene->planes[k], r, tmin, limit, &t) &&
            beats(t, SURFACE_PLANE, k, found, best)) {
            *best = (Hit){.t = t, .kind = SURFACE_PLANE, .index = k};
            world_complete_hit(scene, r, best);
            found = true;
        }
    }
    return found;
}

/* Tells whether any plane lies on ray r with tmin < t < tmax. */
static bool planes_blocked(const Scene *scene, Ray r, double tmin, double tmax)
{
    double t;
    for (int k = 0; k < scene->plane_count; k++)
        if (plane_intersect(&scene->planes[k], r, tmin, tmax, &t))
            return true;
    return false;
}

/* excerpt: accel-boxed-hit */
/* Mode 0: part 1.2's world_hit, but a sphere or triangle is tested only when the ray
 * meets its box; the box is closed and a little larger, so it never rejects a hit. */
static bool boxed_hit(const void *data, Ray r, double tmin, double tmax, Hit *hit)
{
    const Accel *accel = data;
    const Scene *scene = accel->scene;
    BoxRay br = box_ray(r);
    bool found = false;
    double t, t_box;
    for (int k = 0; k < scene->sphere_count; k++)
        if (box_hit(accel->boxes[k], &br, tmin, tmax, &t_box) &&
            sphere_intersect(&scene->spheres[k], r, tmin, tmax, &t)) {
            *hit = (Hit){.t = t, .kind = SURFACE_SPHERE, .index = k};
            tmax = t;
            found = true;
        }
    for (int k = 0; k < scene->plane_count; k++)
        if (plane_intersect(&scene->planes[k], r, tmin, tmax, &t)) {
            *hit = (Hit){.t = t, .kind = SURFACE_PLANE, .index = k};
            tmax = t;
            found = true;
        }
    const Box *triangle_boxes = accel->boxes + scene->sphere_count;
    TriangleHit th;
    for (int k = 0; k < scene->triangle_count; k++) {
        if (!box_hit(triangle_boxes[k], &br, tmin, tmax, &t_box))
            continue;
        Triangle tri = scene_triangle(scene, k);
        if (triangle_intersect(&tri, r, tmin, tmax, &th)) {
            *hit = (Hit){.t = th.t, .kind = SURFACE_TRIANGLE, .index = k};
            tmax = th.t;
            found = true;
        }
    }
    if (found)
        world_complete_hit(scene, r, hit);
    return found;
}
/* end excerpt: accel-boxed-hit */

/* Mode 0: whether anything lies on the ray, stopping at the first surface found. */
static bool boxed_blocked(const void *data, Ray r, double tmin, double tmax)
{
    const Accel *accel = data;
    const Scene *scene = accel->scene;
    BoxRay br = box_ray(r);
    double t, t_box;
    for (int k = 0; k < scene->sphere_count; k++)
        if (box_hit(accel->boxes[k], &br, tmin, tmax, &t_box) &&
            sphere_intersect(&scene->spheres[k], r, tmin, tmax, &t))
            return true;
    const Box *triangle_boxes = accel->boxes + scene->sphere_count;
    TriangleHit th;
    for (int k = 0; k < scene->triangle_count; k++) {
        if (!box_hit(triangle_boxes[k], &br, tmin, tmax, &t_box))
            continue;
        Triangle tri = scene_triangle(scene, k);
        if (triangle_intersect(&tri, r, tmin, tmax, &th))
            return true;
    }
    return planes_blocked(scene, r, tmin, tmax);
}

/* excerpt: accel-box-hit */
/* Mode 1: the boxes instead of the spheres and triangles, as surfaces in their own
 * right: the t where the ray meets the box, the face's axis normal, the surface's
 * material. Planes have no box and are drawn as they are. */
static bool surface_boxes_hit(const void *data, Ray r, double tmin, double tmax, Hit *hit)
{
    const Accel *accel = data;
    const Scene *scene = accel->scene;
    bool found = false;
    int n = scene->sphere_count + scene->triangle_count;
    for (int k = 0; k < n; k++) {
        BoxHit face;
        if (!box_hit_face(accel->boxes[k], r, tmin, tmax, &face))
            continue;
        Hit h = {.t = face.t, .point = ray_at(r, face.t), .normal = box_face_normal(&face)};
        bvh_prim_surface(scene, (uint32_t)k, &h);
        *hit = h;
        tmax = face.t;
        found = true;
    }
    return planes_hit(scene, r, tmin, tmax, found, hit);
}
/* end excerpt: accel-box-hit */

/* Mode 1: whether any box or plane lies on the ray. */
static bool surface_boxes_blocked(const void *data, Ray r, double tmin, double tmax)
{
    const Accel *accel = data;
    int n = accel->scene->sphere_count + accel->scene->triangle_count;
    BoxHit face;
    for (int k = 0; k < n; k++)
        if (box_hit_face(accel->boxes[k], r, tmin, tmax, &face))
            return true;
    return planes_blocked(accel->scene, r, tmin, tmax);
}

/* Mode 2: the BVH's leaf boxes instead of the spheres and triangles; planes as they are. */
static bool leaf_boxes_hit(const void *data, Ray r, double tmin, double tmax, Hit *hit)
{
    const Accel *accel = data;
    bool found = bvh_hit_leaf_boxes(&accel->bvh, r, tmin, tmax, hit);
    return planes_hit(accel->scene, r, tmin, found ? hit->t : tmax, found, hit);
}

/* Mode 2: whether any leaf box or plane lies on the ray. */
static bool leaf_boxes_blocked(const void *data, Ray r, double tmin, double tmax)
{
    const Accel *accel = data;
    Hit hit;
    return bvh_hit_leaf_boxes(&accel->bvh, r, tmin, tmax, &hit) ||
           planes_blocked(accel->scene, r, tmin, tmax);
}

/* excerpt: accel-bvh-hit */
/* Mode 3: the closest sphere or triangle from the BVH, then the planes, which have no
 * box; the winner's point and normal are worked out once, at the end. */
static bool bvh_surfaces_hit(const void *data, Ray r, double tmin, double tmax, Hit *hit)
{
    const Accel *accel = data;
    bool found = bvh_hit(&accel->bvh, r, tmin, tmax, hit);
    if (found)
        world_complete_hit(accel->scene, r, hit);
    return planes_hit(accel->scene, r, tmin, found ? hit->t : tmax, found, hit);
}

/* Mode 3: a shadow ray stops at the first surface the BVH finds, or at a plane. */
static bool bvh_surfaces_blocked(const void *data, Ray r, double tmin, double tmax)
{
    const Accel *accel = data;
    return bvh_blocked(&accel->bvh, r, tmin, tmax) || planes_blocked(accel->scene, r, tmin, tmax);
}
/* end excerpt: accel-bvh-hit */

/* Returns the Surfaces that answer the tracer's questions in accel's mode. */
Surfaces accel_surfaces(const Accel *accel)
{
    switch (accel->mode) {
    case ACCEL_BOXED: return (Surfaces){boxed_hit, boxed_blocked, accel};
    case ACCEL_SURFACE_BOXES: return (Surfaces){surface_boxes_hit, surface_boxes_blocked, accel};
    case ACCEL_LEAF_BOXES: return (Surfaces){leaf_boxes_hit, leaf_boxes_blocked, accel};
    case ACCEL_BVH: break;
    }
    return (Surfaces){bvh_surfaces_hit, bvh_surfaces_blocked, accel};
}

/* Returns how many boxes and primitives ray r is tested against to find its closest hit
 * in accel's mode, for --view box-tests: with the BVH (modes 2 and 3) the nodes' boxes
 * and the leaves' primitives it visits (bvh_count_tests), in modes 0 and 1 every
 * surface's box; and every plane, which has no box. */
long accel_count_tests(const Accel *accel, Ray r)
{
    const Scene *s = accel->scene;
    if (accel->mode == ACCEL_BVH || accel->mode == ACCEL_LEAF_BOXES)
        return bvh_count_tests(&accel->bvh, r) + s->plane_count;
    return s->sphere_count + s->triangle_count + s->plane_count;
}
