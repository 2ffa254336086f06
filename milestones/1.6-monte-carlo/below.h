/* below.h: the part that part 1.6 builds on, named in one place: its tracer and what it does. */
#ifndef RAYTRA_BELOW_H
#define RAYTRA_BELOW_H

#include "dielectric.h"
#include "light.h"
#include "refract.h"
#include "transmit.h"

/* excerpt: below */
/* Part 1.6 samples pixels and area lights around the tracer of the part below it, part
 * 1.3's today. With part 1.5, Below becomes its Refractor (which begins with a Tracer,
 * so below_tracer is &(b)->tracer), and these lines call refract_make,
 * refract_radiance, transmit_direct_radiance and transmit_light (glass lets a
 * filtered part of the light through). */
typedef Refractor Below;
#define below_tracer(b) (&(b)->tracer)
#define BELOW_DIRECT transmit_direct_radiance /* ambient, point and directional lights */

/* Returns the tracer of the part below, over scene and surfaces. */
static inline Below below_make(const Scene *scene, Surfaces surfaces, const Options *opts)
{
    FresnelModel fresnel = FRESNEL_SCHLICK; /* --fresnel is checked in setup */
    if (opts->fresnel_name != NULL)
        dielectric_fresnel_from_name(opts->fresnel_name, &fresnel);
    return refract_make(scene, surfaces, fresnel, opts);
}

/* Returns the radiance along r, as the part below traces it. */
static inline Color below_radiance(const Below *below, Ray r, int depth, Path *path)
{
    return refract_radiance(below, r, depth, path);
}

/* Returns the fraction of the light in that reaches hit: all or nothing, by a shadow ray. */
static inline Color below_light_through(const Below *below, const Hit *hit, Ray r,
                                        const Incident *in, Path *path)
{
    return transmit_light(below, hit, r, in, path);
}
/* end excerpt: below */

#endif
