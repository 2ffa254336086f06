/* refract.h: the radiance along a ray through glass, reflected and refracted (textbook 13.1).
 * Slide 13 ("if the surface is transparent, trace a transmission ray"). */
#ifndef RAYTRA_REFRACT_H
#define RAYTRA_REFRACT_H

#include <stdbool.h>

#include "cli.h"
#include "dielectric.h"
#include "hit.h"
#include "tracer.h"

/* How part 1.5 traces glass: the context of its hooks and of refract_trace. */
typedef struct {
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
extern const TracerHooks refract_hooks;

bool refract_init(Refractor *rf, const Scene *scene, const Options *opts);
Hit refract_glass_hit(const Scene *scene, const Hit *hit);
Color refract_trace(const Refractor *rf, const Tracer *tr, Ray r, RayKind kind, int depth,
                    double weight, Path *path);

#endif
