/* world.c: the closest hit, by testing the ray against every sphere, plane and triangle. */
#include "world.h"

#include "plane.h"
#include "sphere.h"
#include "triangle.h"

/* starter: todo */
/* excerpt: world-hit */
/* Finds the nearest surface that ray r meets with tmin < t < tmax; fills in hit. */
bool world_hit(const Scene *scene, Ray r, double tmin, double tmax, Hit *hit)
{
    /* Each test only looks closer than the best hit so far: tmax shrinks as we go. */
    bool found = false;
    double t;
    for (int k = 0; k < scene->sphere_count; k++)
        if (sphere_intersect(&scene->spheres[k], r, tmin, tmax, &t)) {
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
    TriangleHit th;
    for (int k = 0; k < scene->triangle_count; k++)
        if (triangle_intersect(&scene->triangles[k], r, tmin, tmax, &th)) {
            *hit = (Hit){.t = th.t, .kind = SURFACE_TRIANGLE, .index = k};
            tmax = th.t;
            found = true;
        }
    /* The point, normal and material are worked out once, for the winner only. */
    if (found)
        world_complete_hit(scene, r, hit);
    return found;
}
/* end excerpt: world-hit */

/* starter: todo */
/* excerpt: world-complete-hit */
/* Fills in the point, unit normal, side and material of a hit whose t, kind and index are known. */
void world_complete_hit(const Scene *scene, Ray r, Hit *hit)
{
    hit->point = ray_at(r, hit->t);
    switch (hit->kind) {
    case SURFACE_SPHERE: {
        /* Slide 53 ("unit normal at intersection is"): the unit normal at p is (p - O) / R. */
        const Sphere *s = &scene->spheres[hit->index];
        hit->normal = vec3_scale(vec3_sub(hit->point, s->center), 1 / s->radius);
        hit->material = s->material;
        break;
    }
    case SURFACE_PLANE:
        hit->normal = scene->planes[hit->index].normal;
        hit->material = scene->planes[hit->index].material;
        break;
    case SURFACE_TRIANGLE:
        hit->normal = triangle_normal(&scene->triangles[hit->index]);
        hit->material = scene->triangles[hit->index].material;
        break;
    }
    /* The ray travels along d: it meets the back when d points the way the normal does. */
    hit->back_face = vec3_dot(r.dir, hit->normal) > 0;
}
/* end excerpt: world-complete-hit */
