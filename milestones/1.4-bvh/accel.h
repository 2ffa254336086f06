/* accel.h: the four ways of part 1.4 (the course's modes 0-3) to answer the tracer's Surfaces. */
#ifndef RAYTRA_ACCEL_H
#define RAYTRA_ACCEL_H

#include "bvh.h" /* and box.h, scene.h, stdbool.h */
#include "cli.h"
#include "surfaces.h"

/* The course's third argument, raytra scene_file output_image [0|1|2|3]. */
typedef enum {
    ACCEL_BOXED = 0,         /* every surface, each first rejected by its own box */
    ACCEL_SURFACE_BOXES = 1, /* every surface's box drawn instead of the surface */
    ACCEL_LEAF_BOXES = 2,    /* the BVH's leaf boxes drawn instead of the surfaces */
    ACCEL_BVH = 3            /* the BVH: the default */
} AccelMode;

/* The geometry of a scene made ready for one mode. */
typedef struct {
    AccelMode mode;
    const Scene *scene;
    Box *boxes; /* modes 0 and 1: every surface's box, by surface number */
    Bvh bvh;    /* modes 2 and 3 */
    double build_seconds;
} Accel;

extern const CliOption accel_options[];
extern const CliOption *const accel_part_options[];

bool accel_build(Accel *accel, const Scene *scene, AccelMode mode);
Surfaces accel_surfaces(const Accel *accel);
void accel_free(Accel *accel);
AccelMode accel_mode(const Options *opts);

#endif
