/* world.c: the closest hit, by testing the ray against every sphere, plane and triangle. */
#include "world.h"

#include "plane.h"
#include "sphere.h"
#include "triangle.h"

/* starter: todo */
/* Finds where ray r meets surface number s of scene with tmin < t < tmax, and sets
 * hit's t, kind and index. The surfaces are numbered spheres first, then planes, then
 * triangles: the order in which world_hit tests them. */
bool world_intersect(const Scene *scene, int s, Ray r, double tmin, double tmax, Hit *hit)
{
    double t = 0;
    bool met;
    SurfaceKind kind;
    if (s < scene->sphere_count) {
        kind = SURFACE_SPHERE;
        met = sphere_intersect(&scene->spheres[s], r, tmin, tmax, &t);
    } else if ((s -= scene->sphere_count) < scene->plane_count) {
        kind = SURFACE_PLANE;
        met = plane_intersect(&scene->planes[s], r, tmin, tmax, &t);
    } else {
        kind = SURFACE_TRIANGLE;
        s -= scene->plane_count;
        Triangle tri = scene_triangle(scene, s);
        TriangleHit th;
        met = triangle_intersect(&tri, r, tmin, tmax, &th);
        if (met)
            t = th.t;
    }
    if (met)
        *hit = (Hit){.t = t, .kind = kind, .index = s};
    return met;
}

/* starter: todo */
/* Finds the nearest surface that ray r meets with tmin < t < tmax; fills in hit. */
bool world_hit(const Scene *scene, Ray r, double tmin, double tmax, Hit *hit)
{
    /* Each test only looks closer than the best hit so far: tmax shrinks as we go. */
    bool found = false;
    int surfaces = scene->sphere_count + scene->plane_count + scene->triangle_count;
    for (int s = 0; s < surfaces; s++)
        if (world_intersect(scene, s, r, tmin, tmax, hit)) {
            tmax = hit->t;
            found = true;
        }
    /* The point, normal and material are worked out once, for the winner only. */
    if (found)
        world_complete_hit(scene, r, hit);
    return found;
}

/* starter: todo */
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
    case SURFACE_TRIANGLE: {
        Triangle tri = scene_triangle(scene, hit->index);
        hit->normal = triangle_normal(&tri);
        hit->material = scene->triangles[hit->index].material;
        break;
    }
    }
    /* The ray travels along d: it meets the back when d points the way the normal does. */
    hit->back_face = vec3_dot(r.dir, hit->normal) > 0;
}

/* Returns the scene file's line of the surface hit. */
static int surface_line(const Scene *scene, const Hit *hit)
{
    switch (hit->kind) {
    case SURFACE_SPHERE: return scene->spheres[hit->index].line;
    case SURFACE_PLANE: return scene->planes[hit->index].line;
    case SURFACE_TRIANGLE: return scene->triangles[hit->index].line;
    }
    return 0;
}

/* Prints what a ray hit for --trace-pixel: the surface and its line, t, the point, the
 * normal, the side, and the material. */
void world_explain_hit(const Explain *e, int depth, const Hit *hit)
{
    if (e == NULL)
        return;
    static const char *const kinds[] = {"sphere", "plane", "triangle"};
    const Scene *scene = e->scene;
    const Material *m = &scene->materials[hit->material];
    char where[300], point[96], normal[96];
    explain_line(e, depth, "hits %s %d%s at t = %.9g", kinds[hit->kind], hit->index,
                 explain_where(e, surface_line(scene, hit), where, sizeof where), hit->t);
    explain_line(
        e, depth + 1, "point %s, normal %s, %s face", explain_vec3(hit->point, point, sizeof point),
        explain_vec3(hit->normal, normal, sizeof normal), hit->back_face ? "back" : "front");
    explain_line(e, depth + 1,
                 "material %d%s: kd (%.6g, %.6g, %.6g), ks (%.6g, %.6g, %.6g), p %.6g, "
                 "km (%.6g, %.6g, %.6g)",
                 hit->material, explain_where(e, m->line, where, sizeof where), m->diffuse.r,
                 m->diffuse.g, m->diffuse.b, m->specular.r, m->specular.g, m->specular.b, m->phong,
                 m->mirror.r, m->mirror.g, m->mirror.b);
}

/* Returns a number for the surface hit, different for every surface of the scene:
 * spheres first, then planes, then triangles. */
int world_surface_id(const Scene *scene, const Hit *hit)
{
    switch (hit->kind) {
    case SURFACE_SPHERE: return hit->index;
    case SURFACE_PLANE: return scene->sphere_count + hit->index;
    case SURFACE_TRIANGLE: return scene->sphere_count + scene->plane_count + hit->index;
    }
    return 0;
}
