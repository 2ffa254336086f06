/* trace.h: the radiance along a ray, by recursive ray tracing (textbook chapter 4).
 * Slide 13 ("recursive ray tracing - pseudocode"). */
#ifndef RAYTRA_TRACE_H
#define RAYTRA_TRACE_H

#include "camera.h"
#include "cli.h"
#include "debugview.h"
#include "tracer.h"

/* What of a scene the tracer renders, for the note on what a part ignores: area lights
 * wait for part 1.6, and part 1.5 adds refraction. */
#define TRACER_FEATURES                                                                            \
    (FEATURE_SPHERES | FEATURE_PLANES | FEATURE_TRIANGLES | FEATURE_POINT_LIGHTS |                 \
     FEATURE_DIRECTIONAL_LIGHTS | FEATURE_AMBIENT_LIGHT | FEATURE_MIRRORS | FEATURE_SHADING)

/* What the pixels of parts 1.3 to 1.5 read: the camera, and the tracer behind it. part
 * is the part's own state, which its other callbacks read. */
typedef struct {
    Camera camera;
    const Tracer *tracer;
    void *part;
} TraceView;

extern const CliOption trace_options[];
extern const CliOption *const trace_part_options[];

Color trace_radiance(const Tracer *tr, Ray r, int depth, Path *path);
Color tracer_trace(const Tracer *tr, Ray r, RayKind kind, int depth, Path *path);
void trace_probe(const Tracer *tr, Ray r, unsigned features, Probe *probe);
Color trace_view_pixel(const void *ctx, int i, int j, RayStats *stats);
void trace_view_probe(const void *ctx, int i, int j, Probe *probe);
void trace_view_lines(const void *ctx, int sample, double *fewest, double *most);

#endif
