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
    clock_t start = clock();
    *accel = (Accel){.mode = mode, .scene = scene};
    bool ok;
    if (mode == ACCEL_BOXED || mode == ACCEL_SURFACE_BOXES) {
        int n = scene->sphere_count + scene->plane_count + scene->triangle_count;
        accel->boxes = malloc((size_t)(n > 0 ? n : 1) * sizeof *accel->boxes);
        ok = accel->boxes != NULL;
        for (int s = 0; ok && s < n; s++)
            accel->boxes[s] = box_of_surface(scene, s);
    } else {
        ok = bvh_build(&accel->bvh, scene);
    }
    accel->build_seconds = (double)(clock() - start) / CLOCKS_PER_SEC;
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

/* Mode 0: part 1.2's world_hit, but a surface is tested only when the ray meets its box;
 * the box is closed and a little larger, so it never rejects a hit (a plane's box is
 * all of space). With any, stops at the first surface found: a shadow ray's question. */
static bool boxed_search(const Accel *accel, Ray r, double tmin, double tmax, Hit *hit, bool any)
{
    const Scene *scene = accel->scene;
    BoxRay br = box_ray(r);
    bool found = false;
    double t_box;
    int surfaces = scene->sphere_count + scene->plane_count + scene->triangle_count;
    for (int s = 0; s < surfaces && !(found && any); s++)
        if (box_hit(accel->boxes[s], &br, tmin, tmax, &t_box) &&
            world_intersect(scene, s, r, tmin, tmax, hit)) {
            tmax = hit->t;
            found = true;
        }
    if (found && !any)
        world_complete_hit(scene, r, hit);
    return found;
}

/* Modes 1 and 2: box b drawn in place of surface s, as a surface in its own right: when
 * the ray meets it with tmin < t < *tmax, fills in hit (its t, the face's axis normal
 * from box_hit_face, the surface's material) and lowers *tmax to t. */
static bool box_drawn(const Scene *scene, Box b, int s, Ray r, double tmin, double *tmax, Hit *hit)
{
    double t;
    Vec3 normal;
    if (!box_hit_face(b, r, tmin, *tmax, &t, &normal))
        return false;
    int triangle = s - scene->sphere_count - scene->plane_count;
    bool sphere = s < scene->sphere_count;
    *hit = (Hit){.t = t, .point = ray_at(r, t), .normal = normal,
                 .kind = sphere ? SURFACE_SPHERE : SURFACE_TRIANGLE,
                 .index = sphere ? s : triangle,
                 .material =
                     sphere ? scene->spheres[s].material : scene->triangles[triangle].material};
    *tmax = t;
    return true;
}

/* Mode 2: a leaf's box (its primitives' boxes together) drawn, in the material of its
 * first primitive, into the Hit that state is. */
static bool leaf_box(const Bvh *bvh, BvhRef leaf, Ray r, double tmin, double *tmax, void *state)
{
    Box box = box_empty();
    for (uint32_t k = leaf.index; k < leaf.index + leaf.count; k++)
        box = box_union(box, box_of_surface(bvh->scene, bvh->prims[k]));
    box_drawn(bvh->scene, box, bvh->prims[leaf.index], r, tmin, tmax, state);
    return false;
}

/* Modes 1 and 2: the boxes drawn (every surface's, or the BVH's leaves') instead of the
 * spheres and triangles, then the planes, which have no box, as they are; each lowers t
 * from tmax to what it shows, so something was found when t < tmax. */
static bool boxes_hit(const Accel *accel, Ray r, double tmin, double tmax, Hit *hit)
{
    const Scene *scene = accel->scene;
    double t = tmax;
    long tests = 0;
    if (accel->mode == ACCEL_LEAF_BOXES)
        bvh_traverse(&accel->bvh, r, tmin, &t, leaf_box, hit, &tests);
    int spheres = scene->sphere_count, planes = spheres + scene->plane_count;
    for (int s = 0; accel->mode == ACCEL_SURFACE_BOXES && s < planes + scene->triangle_count; s++)
        if (s < spheres || s >= planes)
            box_drawn(scene, accel->boxes[s], s, r, tmin, &t, hit);
    for (int s = spheres; s < planes; s++)
        if (world_intersect(scene, s, r, tmin, t, hit)) {
            world_complete_hit(scene, r, hit);
            t = hit->t;
        }
    return t < tmax;
}

/* Finds the closest surface on ray r with tmin < t < tmax in accel's mode (data). */
static bool accel_hit(const void *data, Ray r, double tmin, double tmax, Hit *hit)
{
    const Accel *accel = data;
    long tests = 0; /* counted for --view box-tests only (accel_tests) */
    return accel->mode == ACCEL_BOXED ? boxed_search(accel, r, tmin, tmax, hit, false)
           : accel->mode == ACCEL_BVH ? bvh_hit(&accel->bvh, r, tmin, tmax, hit, &tests)
                                      : boxes_hit(accel, r, tmin, tmax, hit);
}

/* Tells whether anything in accel's mode (data) lies on ray r with tmin < t < tmax: in
 * modes 0 and 3 it stops at the first surface found, a shadow ray's question. */
static bool accel_blocked(const void *data, Ray r, double tmin, double tmax)
{
    const Accel *accel = data;
    Hit hit;
    return accel->mode == ACCEL_BOXED ? boxed_search(accel, r, tmin, tmax, &hit, true)
           : accel->mode == ACCEL_BVH ? bvh_blocked(&accel->bvh, r, tmin, tmax)
                                      : boxes_hit(accel, r, tmin, tmax, &hit);
}

/* Returns how many boxes and primitives ray r is tested against to find its closest hit
 * in accel's mode (data), for --view box-tests: every plane, which has no box, and the
 * BVH's count (modes 2 and 3) or every other surface's box (modes 0 and 1). */
static long accel_tests(const void *data, Ray r)
{
    const Accel *accel = data;
    const Scene *s = accel->scene;
    long tests = s->plane_count;
    Hit hit;
    if (accel->mode == ACCEL_BOXED || accel->mode == ACCEL_SURFACE_BOXES)
        return tests + s->sphere_count + s->triangle_count;
    bvh_hit(&accel->bvh, r, 0, INFINITY, &hit, &tests);
    return tests;
}

/* Returns the Surfaces that answer the tracer's questions in accel's mode. */
Surfaces accel_surfaces(const Accel *accel)
{
    return (Surfaces){accel_hit, accel_blocked, accel_tests, accel};
}
