/* trace.h: the radiance along a ray, by recursive ray tracing (textbook chapter 4).
 * Slide 13 ("recursive ray tracing - pseudocode"). */
#ifndef RAYTRA_TRACE_H
#define RAYTRA_TRACE_H

#include <stdbool.h>

#include "camera.h"
#include "cli.h"
#include "color.h"
#include "debugview.h"
#include "explain.h"
#include "ray.h"
#include "render.h"
#include "scene.h"
#include "surfaces.h"

/* What one path carries down its bounces: its ray counts and, from part 1.6 on,
 * the random numbers of its pixel sample (NULL before). */
typedef struct {
    RayStats *stats;
    const void *sample;
} Path;

typedef struct Tracer Tracer;

/* What of a scene the tracer renders, for the note on what a part ignores; part 1.5
 * adds refraction. */
#define TRACER_FEATURES                                                                            \
    (FEATURE_SPHERES | FEATURE_PLANES | FEATURE_TRIANGLES | FEATURE_POINT_LIGHTS |                 \
     FEATURE_DIRECTIONAL_LIGHTS | FEATURE_AREA_LIGHTS | FEATURE_AMBIENT_LIGHT | FEATURE_MIRRORS |  \
     FEATURE_SHADING)

/* The light a hit receives straight from the lights; depth counts the bounces before r. */
typedef Color (*DirectFn)(const Tracer *tr, const Hit *hit, Ray r, int depth, Path *path);

/* excerpt: tracer-struct */
/* Everything a traced ray needs besides the ray, shared by every thread: read only. */
struct Tracer {
    const Scene *scene;
    Surfaces surfaces; /* how a ray finds what it hits */
    int max_depth;     /* reflected rays a path may take */
    bool two_sided;    /* shade back faces with their own material, not yellow */
    double offset;     /* where secondary rays start: see secondary_ray */
    DirectFn direct;   /* direct_radiance; part 1.6 plugs in area-light sampling */
    const Explain *explain; /* --trace-pixel: where each step is told; NULL when not */
};
/* end excerpt: tracer-struct */

Tracer tracer_make(const Scene *scene, Surfaces surfaces, const Options *opts);
Color trace_radiance(const Tracer *tr, Ray r, int depth, Path *path);
void trace_probe(const Tracer *tr, Ray r, Probe *probe);
Color trace_camera_pixel(const Tracer *tr, const Camera *cam, int i, int j, RayStats *stats);

#endif
