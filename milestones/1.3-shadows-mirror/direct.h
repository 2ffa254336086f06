/* direct.h: the light a surface point receives straight from the lights, shadows included. */
#ifndef RAYTRA_DIRECT_H
#define RAYTRA_DIRECT_H

#include <stdbool.h>

#include "color.h"
#include "hit.h"
#include "light.h"
#include "render.h"
#include "tracer.h"

Ray direct_shadow_ray(const Tracer *tr, const Hit *hit, Ray r, const Incident *in, double *tmax);
bool direct_in_shadow(const Tracer *tr, const Hit *hit, Ray r, const Incident *in, int depth,
                      Path *path);
Color direct_through(const void *ctx, const Tracer *tr, const Hit *hit, Ray r, const Incident *in,
                     int depth, Path *path);
Color direct_incident(const Tracer *tr, const Hit *hit, Ray r, const Incident *in, int depth,
                      Path *path);
Color direct_light(const void *ctx, const Tracer *tr, const Hit *hit, Ray r, const Light *light,
                   int depth, Path *path);
Color direct_ambient(const Tracer *tr, const Material *m, int depth);
Color direct_radiance(const Tracer *tr, const Hit *hit, Ray r, int depth, Path *path);

extern const TracerHooks direct_hooks;

#endif
