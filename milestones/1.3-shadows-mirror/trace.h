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
#include "hit.h"
#include "light.h"
#include "ray.h"
#include "render.h"
#include "scene.h"
#include "surfaces.h"

/* What one path carries down its bounces: its ray counts; from part 1.5 on, its share
 * of the pixel (weight, 1 for a camera ray); from part 1.6 on, the random numbers of its
 * pixel sample (NULL before). */
typedef struct {
    RayStats *stats;
    double weight;
    const void *sample;
} Path;

typedef struct Tracer Tracer;

/* What of a scene the tracer renders, for the note on what a part ignores: area lights
 * wait for part 1.6, and part 1.5 adds refraction. */
#define TRACER_FEATURES                                                                            \
    (FEATURE_SPHERES | FEATURE_PLANES | FEATURE_TRIANGLES | FEATURE_POINT_LIGHTS |                 \
     FEATURE_DIRECTIONAL_LIGHTS | FEATURE_AMBIENT_LIGHT | FEATURE_MIRRORS | FEATURE_SHADING)

/* excerpt: tracer-hooks */
/* The three hooks a later part plugs into, each a function and the context it is handed
 * (its part's own state; NULL for part 1.3's). tracer_make sets part 1.3's own
 * (tracer_hooks); a later part replaces one by assigning its function and context. */

/* The radiance arriving along ray r, depth bounces after the camera ray: part 1.3's
 * trace_radiance; part 1.5 traces glass. */
typedef Color (*RadianceFn)(const void *ctx, const Tracer *tr, Ray r, int depth, Path *path);
/* The light that one light sends back along r from hit, shadows included: part 1.3's
 * direct_light, which leaves area lights dark; part 1.6 samples them. */
typedef Color (*LightFn)(const void *ctx, const Tracer *tr, const Hit *hit, Ray r,
                         const Light *light, int depth, Path *path);
/* The fraction of the light in that reaches hit's point, per channel: part 1.3's
 * direct_through, all or nothing by a shadow ray; part 1.5 lets some through glass. */
typedef Color (*ThroughFn)(const void *ctx, const Tracer *tr, const Hit *hit, Ray r,
                           const Incident *in, int depth, Path *path);

typedef struct {
    RadianceFn radiance;
    const void *radiance_ctx;
    LightFn light;
    const void *light_ctx;
    bool light_areas; /* the light hook lights area lights: false for part 1.3's */
    ThroughFn through;
    const void *through_ctx;
} TracerHooks;
/* end excerpt: tracer-hooks */

/* excerpt: tracer-struct */
/* Everything a traced ray needs besides the ray, shared by every thread: read only. */
struct Tracer {
    const Scene *scene;
    Surfaces surfaces;      /* how a ray finds what it hits */
    int max_depth;          /* reflected rays a path may take */
    bool two_sided;         /* shade back faces with their own material, not yellow */
    double offset;          /* where secondary rays start: see secondary_ray */
    TracerHooks hooks;      /* part 1.3's own, or what a later part plugs in */
    const Explain *explain; /* --trace-pixel: where the seams tell each step; NULL when not */
};
/* end excerpt: tracer-struct */

/* What the pixels of part 1.3 and of the later parts that keep them read: the camera, and
 * the tracer behind it. part is the part's own state, which its other callbacks read. */
typedef struct {
    Camera camera;
    const Tracer *tracer;
    void *part;
} TraceView;

extern const TracerHooks tracer_hooks;
extern const CliOption trace_options[];
extern const CliOption *const trace_part_options[];

Tracer tracer_make(const Scene *scene, Surfaces surfaces, const Options *opts);
Color trace_radiance(const Tracer *tr, Ray r, int depth, Path *path);
bool tracer_hit(const Tracer *tr, Ray r, int depth, Hit *hit);
bool tracer_blocked(const Tracer *tr, Ray shadow, double tmax, int depth, Path *path);
bool tracer_shadow_hit(const Tracer *tr, Ray shadow, double tmax, int crossed, int depth, Hit *hit,
                       Path *path);
Color tracer_trace(const Tracer *tr, Ray r, RayKind kind, int depth, Path *path);
Color tracer_light(const Tracer *tr, const Hit *hit, Ray r, int k, int depth, Path *path);
Color tracer_through(const Tracer *tr, const Hit *hit, Ray r, const Incident *in, int depth,
                     Path *path);
void tracer_trace_lines(const Tracer *tr, double rays, double area_rays, double *fewest,
                        double *most);
void trace_probe(const Tracer *tr, Ray r, Probe *probe);
Color trace_camera_pixel(const Tracer *tr, const Camera *cam, int i, int j, RayStats *stats);
Color trace_view_pixel(const void *ctx, int i, int j, RayStats *stats);
void trace_view_probe(const void *ctx, int i, int j, Probe *probe);
void trace_view_lines(const void *ctx, int sample, double *fewest, double *most);

#endif
