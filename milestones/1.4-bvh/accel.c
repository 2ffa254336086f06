/* accel.c: Surfaces for the course's modes: boxes as rejection tests, boxes drawn, and the BVH. */
#include "accel.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "world.h"

/* Builds what mode needs for scene: the surfaces' boxes or the BVH; false (reported, with
 * nothing left to free) when out of memory. */
bool accel_build(Accel *accel, const Scene *scene, AccelMode mode)
{
    struct timespec start, end;
    clock_gettime(CLOCK_MONOTONIC, &start);
    *accel = (Accel){.mode = mode, .scene = scene};
    bool ok = true;
    if (mode == ACCEL_BOXED || mode == ACCEL_SURFACE_BOXES) {
        int n = scene->sphere_count + scene->plane_count + scene->triangle_count;
        accel->boxes = malloc((size_t)(n > 0 ? n : 1) * sizeof *accel->boxes);
        ok = accel->boxes != NULL;
        for (int s = 0; ok && s < n; s++)
            accel->boxes[s] = box_of_surface(scene, s);
    } else {
        ok = bvh_build(&accel->bvh, scene);
    }
    clock_gettime(CLOCK_MONOTONIC, &end);
    accel->build_seconds =
        (double)(end.tv_sec - start.tv_sec) + (end.tv_nsec - start.tv_nsec) * 1e-9;
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

/* Fills in hit as the face of surface s's box that ray r meets at t, with that face's
 * normal, in the surface's material: how modes 1 and 2 draw a box in its place. */
static void box_face_hit(const Scene *scene, int s, Ray r, double t, Vec3 normal, Hit *hit)
{
    int planes = scene->sphere_count + scene->plane_count;
    if (s < scene->sphere_count)
        *hit = (Hit){.kind = SURFACE_SPHERE, .index = s, .material = scene->spheres[s].material};
    else
        *hit = (Hit){.kind = SURFACE_TRIANGLE,
                     .index = s - planes,
                     .material = scene->triangles[s - planes].material};
    hit->t = t;
    hit->point = ray_at(r, t);
    hit->normal = normal;
}

/* excerpt: accel-boxed-hit */
/* Mode 0: part 1.2's world_hit, but a surface is tested only when the ray meets its box;
 * the box is closed and a little larger, so it never rejects a hit (a plane's box is
 * all of space). */
static bool boxed_hit(const void *data, Ray r, double tmin, double tmax, Hit *hit)
{
    const Accel *accel = data;
    const Scene *scene = accel->scene;
    BoxRay br = box_ray(r);
    bool found = false;
    double t_box;
    int surfaces = scene->sphere_count + scene->plane_count + scene->triangle_count;
    for (int s = 0; s < surfaces; s++)
        if (box_hit(accel->boxes[s], &br, tmin, tmax, &t_box) &&
            world_intersect(scene, s, r, tmin, tmax, hit)) {
            tmax = hit->t;
            found = true;
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
    double t_box;
    Hit hit;
    int surfaces = scene->sphere_count + scene->plane_count + scene->triangle_count;
    for (int s = 0; s < surfaces; s++)
        if (box_hit(accel->boxes[s], &br, tmin, tmax, &t_box) &&
            world_intersect(scene, s, r, tmin, tmax, &hit))
            return true;
    return false;
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
    int surfaces = scene->sphere_count + scene->plane_count + scene->triangle_count;
    for (int s = 0; s < surfaces; s++) {
        double t;
        Vec3 normal;
        bool plane = s >= scene->sphere_count && s < scene->sphere_count + scene->plane_count;
        if (plane && world_intersect(scene, s, r, tmin, tmax, hit)) {
            world_complete_hit(scene, r, hit);
        } else if (!plane && box_hit_face(accel->boxes[s], r, tmin, tmax, &t, &normal)) {
            box_face_hit(scene, s, r, t, normal, hit);
        } else {
            continue;
        }
        tmax = hit->t;
        found = true;
    }
    return found;
}
/* end excerpt: accel-box-hit */

/* The closest leaf box so far: where the ray meets it, and its leaf's first entry. */
typedef struct {
    bool found;
    uint32_t first;
    double t;
    Vec3 normal;
    double tmax;
} LeafBoxes;

/* Tests a leaf's box (its primitives' boxes together) as if it were a surface, as the
 * BVH's leaf_closest tests primitives: the smaller (t, first entry) wins. */
static bool leaf_box(const Bvh *bvh, BvhRef leaf, Ray r, double tmin, double *tmax, void *state)
{
    LeafBoxes *lb = state;
    Box box = box_empty();
    for (uint32_t k = leaf.index; k < leaf.index + leaf.count; k++)
        box = box_union(box, box_of_surface(bvh->scene, bvh->prims[k]));
    double t;
    Vec3 normal;
    if (box_hit_face(box, r, tmin, lb->tmax, &t, &normal) &&
        (!lb->found || t < lb->t || (t == lb->t && leaf.index < lb->first))) {
        *lb = (LeafBoxes){true, leaf.index, t, normal, lb->tmax};
        *tmax = t;
    }
    return false;
}

/* Mode 2: the BVH's leaf boxes instead of the spheres and triangles, each in the material
 * of its first primitive; planes as they are. */
static bool leaf_boxes_hit(const void *data, Ray r, double tmin, double tmax, Hit *hit)
{
    const Accel *accel = data;
    const Scene *scene = accel->scene;
    LeafBoxes lb = {.tmax = tmax};
    bvh_traverse(&accel->bvh, r, tmin, &tmax, leaf_box, &lb);
    if (lb.found)
        box_face_hit(scene, accel->bvh.prims[lb.first], r, lb.t, lb.normal, hit);
    bool found = lb.found;
    for (int k = 0; k < scene->plane_count; k++)
        if (world_intersect(scene, scene->sphere_count + k, r, tmin, found ? hit->t : lb.tmax,
                            hit)) {
            world_complete_hit(scene, r, hit);
            found = true;
        }
    return found;
}

/* Modes 1 and 2: whether any box drawn, or any plane, lies on the ray. */
static bool boxes_blocked(const void *data, Ray r, double tmin, double tmax)
{
    Hit hit;
    return ((const Accel *)data)->mode == ACCEL_SURFACE_BOXES
               ? surface_boxes_hit(data, r, tmin, tmax, &hit)
               : leaf_boxes_hit(data, r, tmin, tmax, &hit);
}

/* excerpt: accel-bvh-hit */
/* Mode 3: the closest surface, from the BVH. */
static bool bvh_surfaces_hit(const void *data, Ray r, double tmin, double tmax, Hit *hit)
{
    return bvh_hit(&((const Accel *)data)->bvh, r, tmin, tmax, hit);
}

/* Mode 3: a shadow ray stops at the first surface the BVH finds. */
static bool bvh_surfaces_blocked(const void *data, Ray r, double tmin, double tmax)
{
    return bvh_blocked(&((const Accel *)data)->bvh, r, tmin, tmax);
}
/* end excerpt: accel-bvh-hit */

/* Returns the Surfaces that answer the tracer's questions in accel's mode. */
Surfaces accel_surfaces(const Accel *accel)
{
    switch (accel->mode) {
    case ACCEL_BOXED: return (Surfaces){boxed_hit, boxed_blocked, accel};
    case ACCEL_SURFACE_BOXES: return (Surfaces){surface_boxes_hit, boxes_blocked, accel};
    case ACCEL_LEAF_BOXES: return (Surfaces){leaf_boxes_hit, boxes_blocked, accel};
    case ACCEL_BVH: break;
    }
    return (Surfaces){bvh_surfaces_hit, bvh_surfaces_blocked, accel};
}

/* Counts the boxes and primitives the BVH's search for a closest hit tests below at,
 * in bvh_traverse's order: the nearer child first, the other if the hits found since
 * (which lower *tmax) have not ruled it out. */
static long count_below(const Bvh *bvh, BvhRef at, const FloatRay *fr, Ray r, double *tmax)
{
    Hit hit;
    for (uint32_t k = at.index; k < at.index + at.count; k++)
        if (world_intersect(bvh->scene, bvh->prims[k], r, 0, *tmax, &hit))
            *tmax = hit.t;
    if (at.count > 0 || at.index >= (uint32_t)bvh->node_count) /* a leaf, or a tree unfinished */
        return at.count;
    const BvhNode *node = &bvh->nodes[at.index];
    float entry[2];
    int hits = bvh_node_hit(node, fr, box_float_tmax(*tmax), entry);
    long tests = 2;
    for (int k = hits == 3 && entry[1] < entry[0], i = 0; i < 2; i++, k = 1 - k)
        if ((hits >> k & 1) && box_float_reaches(fr, entry[k], box_float_tmax(*tmax)))
            tests += count_below(bvh, node->child[k], fr, r, tmax);
    return tests;
}

/* Returns how many boxes and primitives ray r is tested against to find its closest hit
 * in accel's mode, for --view box-tests: with the BVH (modes 2 and 3) the root's box,
 * two boxes a node it visits and the leaves' primitives, in modes 0 and 1 every
 * surface's box; and every plane, which has no box. */
long accel_count_tests(const Accel *accel, Ray r)
{
    const Scene *s = accel->scene;
    const Bvh *bvh = &accel->bvh;
    if (accel->mode != ACCEL_BVH && accel->mode != ACCEL_LEAF_BOXES)
        return s->sphere_count + s->triangle_count + s->plane_count;
    FloatRay fr = box_float_ray(r, 0, bvh->in_range);
    double tmax = INFINITY;
    float entry[2];
    if (bvh->prim_count == 0 || !(bvh_node_hit(&bvh->top, &fr, INFINITY, entry) & 1))
        return (bvh->prim_count > 0) + s->plane_count;
    return 1 + count_below(bvh, bvh->root, &fr, r, &tmax) + s->plane_count;
}
