/* hit.h: the intersection record: what a ray hit, where, and facing which way.
 * Slide 54 ("for ray/surface intersection tests, we need to record"). */
#ifndef RAYTRA_HIT_H
#define RAYTRA_HIT_H

#include <stdbool.h>

#include "vec3.h"

typedef enum { SURFACE_SPHERE, SURFACE_PLANE, SURFACE_TRIANGLE } SurfaceKind;

typedef struct {
    double t;         /* the ray parameter of the hit */
    Vec3 point;       /* r(t) */
    Vec3 normal;      /* the surface's unit geometric normal: outwards for a sphere,
                         N for a plane, (b - a) x (c - a) for a triangle */
    bool back_face;   /* the ray arrived from the side the normal points away from */
    int material;     /* index into the scene's materials */
    SurfaceKind kind; /* what was hit */
    int index;        /* which sphere, plane or triangle */
} Hit;

#endif
