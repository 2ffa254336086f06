/* tracer.h: what a traced ray needs besides the ray, and the seams that trace and tell it. */
#ifndef RAYTRA_TRACER_H
#define RAYTRA_TRACER_H

#include <stdbool.h>

#include "cli.h"
#include "color.h"
#include "explain.h"
#include "hit.h"
#include "light.h"
#include "ray.h"
#include "render.h"
#include "scene.h"
#include "surfaces.h"

/* What one path carries down its bounces: where its rays are counted. */
typedef struct {
    RayStats *stats;
} Path;

typedef struct Tracer Tracer;

/* excerpt: tracer-hooks */
/* The two hooks through which a part changes how a hit is lit. Each is handed the context
 * the part gave its tracer, with the tracer itself. */

/* The light that one light sends back along r from hit, shadows included: part 1.3's
 * direct_light, which leaves area lights dark; part 1.6 samples them. */
typedef Color (*LightFn)(const void *ctx, const Tracer *tr, const Hit *hit, Ray r,
                         const Light *light, int depth, Path *path);
/* The fraction of the light in that reaches hit's point, per channel: part 1.3's
 * direct_through, all or nothing by a shadow ray; part 1.5 lets some through glass. */
typedef Color (*ThroughFn)(const void *ctx, const Tracer *tr, const Hit *hit, Ray r,
                           const Incident *in, int depth, Path *path);

/* A part's hooks: one table of functions, constant, which the part hands its tracer
 * when it makes it (part 1.3's is direct_hooks). */
typedef struct {
    LightFn light;
    ThroughFn through;
} TracerHooks;
/* end excerpt: tracer-hooks */

/* excerpt: tracer-struct */
/* Everything a traced ray needs besides the ray, shared by every thread: read only. */
struct Tracer {
    const Scene *scene;
    Surfaces surfaces;        /* how a ray finds what it hits */
    int max_depth;            /* reflected rays a path may take */
    bool two_sided;           /* shade back faces with their own material, not yellow */
    double offset;            /* where secondary rays start: see secondary_ray */
    const TracerHooks *hooks; /* the hooks of the part that made the tracer */
    const void *ctx;          /* what they are handed: that part's own state */
    const Explain *explain;   /* --trace-pixel: where the seams tell each step; NULL when not */
};
/* end excerpt: tracer-struct */

Tracer tracer_make(const Scene *scene, Surfaces surfaces, const Options *opts,
                   const TracerHooks *hooks, const void *ctx);
Tracer tracer_extend(const Tracer *below, const TracerHooks *hooks, const void *ctx);
bool tracer_hit(const Tracer *tr, Ray r, int depth, Hit *hit);
bool tracer_blocked(const Tracer *tr, Ray shadow, double tmax, int depth, Path *path);
bool tracer_shadow_hit(const Tracer *tr, Ray shadow, double tmax, int crossed, int depth, Hit *hit,
                       Path *path);
void tracer_cast(const Tracer *tr, Ray r, RayKind kind, int depth, Path *path);
Color tracer_arrived(const Tracer *tr, int depth, Color radiance);
Color tracer_light(const Tracer *tr, const Hit *hit, Ray r, int k, int depth, Path *path);
Color tracer_through(const Tracer *tr, const Hit *hit, Ray r, const Incident *in, int depth,
                     Path *path);
void tracer_trace_lines(const Tracer *tr, double rays, double area_rays, double *fewest,
                        double *most);

#endif
