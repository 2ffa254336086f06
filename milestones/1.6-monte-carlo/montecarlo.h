/* montecarlo.h: Monte Carlo ray tracing: many rays per pixel, many shadow rays per area light. */
#ifndef RAYTRA_MONTECARLO_H
#define RAYTRA_MONTECARLO_H

#include <stdbool.h>
#include <stdint.h>

#include "camera.h"
#include "cli.h"
#include "rng.h"
#include "refract.h"
#include "strata.h"
#include "trace.h"

/* The largest P and S: the command line's limit (--samples, --light-samples). */
#define MONTECARLO_MAX_SIDE 64

/* What part 1.6 renders: what part 1.5 renders, and area lights. */
#define MONTECARLO_FEATURES (TRACER_FEATURES | FEATURE_AREA_LIGHTS | FEATURE_REFRACTION)

/* Everything the pixels read: the geometry and settings every sample's tracer shares,
 * part 1.5's Refractor, and the sampling. */
typedef struct {
    Tracer tracer;       /* the geometry and settings: each sample's tracer extends it */
    Refractor refractor; /* part 1.5's: glass, and shadows through glass */
    Camera camera;
    Sampling sampling;
    int pixel_side; /* P */
    int light_side; /* S */
    uint64_t seed;
} MonteCarlo;

/* One pixel sample, the context of the hooks of the tracer that traces it: the part's
 * settings; its own random numbers, drawn in order at every hit; and, in correlated
 * sampling with S = 1, the stratum of the light its shadow rays use. */
typedef struct {
    const MonteCarlo *mc;
    Rng *rng;
    int stratum;     /* which of strata_side^2 light strata */
    int strata_side; /* P when the light strata follow the pixel's; 0 otherwise */
} Sample;

extern const CliOption montecarlo_options[];
extern const CliOption *const montecarlo_part_options[];

extern const TracerHooks montecarlo_hooks;

bool montecarlo_init(MonteCarlo *mc, const Scene *scene, Surfaces surfaces, const Options *opts);
void montecarlo_light_point(const MonteCarlo *mc, const Sample *sample, int q, double *ru,
                            double *rv);
Color montecarlo_area_radiance(const Sample *sample, const Tracer *tr, const Light *light,
                               const Hit *hit, Ray r, int depth, Path *path);
Color montecarlo_light(const void *ctx, const Tracer *tr, const Hit *hit, Ray r, const Light *light,
                       int depth, Path *path);
void montecarlo_point(const MonteCarlo *mc, Rng *rng, int i, int j, int k, double *x, double *y);
Color montecarlo_pixel(const MonteCarlo *mc, int i, int j, RayStats *stats);
Color montecarlo_sample(const MonteCarlo *mc, int i, int j, int k, RayStats *stats);
void montecarlo_probe(const MonteCarlo *mc, int i, int j, Probe *probe);

#endif
