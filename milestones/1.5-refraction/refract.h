/* refract.h: the radiance along a ray through glass, reflected and refracted (textbook 13.1).
 * Slide 13 ("if the surface is transparent, trace a transmission ray"). */
#ifndef RAYTRA_REFRACT_H
#define RAYTRA_REFRACT_H

#include <stdbool.h>

#include "cli.h"
#include "dielectric.h"
#include "hit.h"
#include "trace.h"

/* Part 1.5's tracer: part 1.3's Tracer, whose radiance and through hooks it takes over
 * (with this Refractor as their context), and how glass reflects. */
typedef struct {
    Tracer tracer;
    FresnelModel fresnel; /* --fresnel: Schlick's approximation or the exact equations */
    double min_weight;    /* --min-weight: rays that count less in their pixel are not traced */
    bool has_glass;       /* some material has an index of refraction */
} Refractor;

/* Tells whether material m is glass: it has an index of refraction. */
static inline bool refract_is_glass(const Material *m)
{
    return m->ior > 0;
}

extern const CliOption refract_options[];
extern const CliOption *const refract_part_options[];

bool refract_init(Refractor *rf, const Scene *scene, Surfaces surfaces, const Options *opts);
Hit refract_glass_hit(const Scene *scene, const Hit *hit);
Color refract_radiance(const void *ctx, const Tracer *tr, Ray r, int depth, Path *path);

#endif
