/* transmit.h: how much of a light reaches a point through glass. */
#ifndef RAYTRA_TRANSMIT_H
#define RAYTRA_TRANSMIT_H

#include "color.h"
#include "hit.h"
#include "light.h"
#include "refract.h"

/* A shadow ray crosses at most this many glass surfaces; beyond, the light counts as blocked. */
#define TRANSMIT_MAX_CROSSINGS 64

Color transmit_light(const void *ctx, const Tracer *tr, const Hit *hit, Ray r, const Incident *in,
                     int depth, Path *path);

#endif
