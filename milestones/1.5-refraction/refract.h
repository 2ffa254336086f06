/* refract.h: the radiance along a ray through glass, reflected and refracted (textbook 13.1).
 * Slide 13 ("if the surface is transparent, trace a transmission ray"). */
#ifndef RAYTRA_REFRACT_H
#define RAYTRA_REFRACT_H

#include <stdbool.h>

#include "cli.h"
#include "dielectric.h"
#include "hit.h"
#include "trace.h"

/* excerpt: refractor-struct */
/* Part 1.5's tracer: part 1.3's Tracer, which it begins with, and how glass reflects.
 * The direct-light hook receives the Tracer; refractor_of gets the whole back. */
typedef struct {
    Tracer tracer;        /* first: a pointer to it is a pointer to the Refractor */
    FresnelModel fresnel; /* --fresnel: Schlick's approximation or the exact equations */
    double min_weight;    /* --min-weight: rays that count less in their pixel are not traced */
    bool has_glass;       /* some material has an index of refraction */
} Refractor;
/* end excerpt: refractor-struct */

/* Returns the Refractor that tr begins; tr must be the tracer of a Refractor. */
static inline const Refractor *refractor_of(const Tracer *tr)
{
    return (const Refractor *)tr;
}

/* Tells whether material m is glass: it has an index of refraction. */
static inline bool refract_is_glass(const Material *m)
{
    return m->ior > 0;
}

Refractor refract_make(const Scene *scene, Surfaces surfaces, FresnelModel fresnel,
                       const Options *opts);
Hit refract_glass_hit(const Scene *scene, const Hit *hit);
Color refract_radiance(const Refractor *rf, Ray r, int depth, Path *path);

#endif
