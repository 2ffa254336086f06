/* montecarlo.h: Monte Carlo ray tracing: many rays per pixel, many shadow rays per area light. */
#ifndef RAYTRA_MONTECARLO_H
#define RAYTRA_MONTECARLO_H

#include <stdbool.h>
#include <stdint.h>

#include "camera.h"
#include "cli.h"
#include "rng.h"
#include "strata.h"
#include "trace.h"

/* The largest P and S: the command line's limit (--samples, --light-samples). */
#define MONTECARLO_MAX_SIDE 64

/* The radiance along a ray, as the part below computes it (1.3's trace_radiance). */
typedef Color (*RadianceFn)(const Tracer *tr, Ray r, int depth, Path *path);

/* excerpt: sample-struct */
/* What a pixel sample carries down its path in Path.sample: its own random numbers,
 * drawn in order at every hit, and, in correlated sampling with S = 1, the stratum of
 * the light its shadow rays use. */
typedef struct {
    Rng *rng;
    int stratum;     /* which of strata_side^2 light strata */
    int strata_side; /* P when the light strata follow the pixel's; 0 otherwise */
} Sample;
/* end excerpt: sample-struct */

/* excerpt: montecarlo-struct */
/* Everything the pixels read. tracer comes first: its direct hook receives &tracer and
 * finds the rest of the struct from it. */
typedef struct {
    Tracer tracer;       /* 1.3's tracer, its direct hook montecarlo_direct_radiance */
    Tracer point_lights; /* the same over point_scene, with 1.3's direct_radiance */
    Scene point_scene;   /* the scene without its area lights */
    RadianceFn radiance; /* the part below's radiance function */
    Camera camera;
    Sampling sampling;
    int pixel_side; /* P */
    int light_side; /* S */
    uint64_t seed;
} MonteCarlo;
/* end excerpt: montecarlo-struct */

bool montecarlo_init(MonteCarlo *mc, const Scene *scene, Surfaces surfaces, RadianceFn radiance,
                     const Options *opts);
void montecarlo_free(MonteCarlo *mc);
Color montecarlo_direct_radiance(const Tracer *tr, const Hit *hit, Ray r, int depth, Path *path);
Color montecarlo_pixel(const MonteCarlo *mc, int i, int j, RayStats *stats);
void montecarlo_probe(const MonteCarlo *mc, int i, int j, Probe *probe);

#endif
