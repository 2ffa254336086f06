/* surfaces.h: the scene's geometry as the tracer queries it, whatever finds the hits. */
#ifndef RAYTRA_SURFACES_H
#define RAYTRA_SURFACES_H

#include <stdbool.h>

#include "hit.h"
#include "ray.h"
#include "scene.h"

/* The questions a tracer asks of the geometry. Part 1.3 answers them by testing every
 * surface; part 1.4 plugs in a bounding volume hierarchy behind the same calls. */
typedef struct {
    /* Finds the closest hit with tmin < t < tmax. */
    bool (*hit)(const void *data, Ray r, double tmin, double tmax, Hit *hit);
    /* Tells whether anything at all lies on the ray with tmin < t < tmax. */
    bool (*blocked)(const void *data, Ray r, double tmin, double tmax);
    /* Returns how many boxes and surfaces the search for the closest hit tests, for
     * --view box-tests. */
    long (*tests)(const void *data, Ray r);
    const void *data;
} Surfaces;

Surfaces surfaces_brute_force(const Scene *scene);

#endif
