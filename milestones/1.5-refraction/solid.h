/* solid.h: whether the glass triangles of a scene enclose solids: closed and consistently wound. */
#ifndef RAYTRA_SOLID_H
#define RAYTRA_SOLID_H

#include <stdbool.h>
#include <stdio.h>

#include "scene.h"

/* What the edges of a scene's glass triangles say about the solids they bound. */
typedef struct {
    long open;       /* edges used by one glass triangle only: a hole */
    long miswound;   /* edges two triangles run the same way: an inconsistent winding */
    bool incomplete; /* out of memory: nothing was checked */
} SolidCheck;

/* One edge of one glass triangle, its corners in a fixed order and the way it runs. */
typedef struct {
    int material;
    Vec3 lo, hi;  /* the corners, the lesser one (by x, then y, then z) first */
    bool forward; /* the triangle runs from lo to hi */
} SolidEdge;

SolidEdge solid_edge(int material, Vec3 p, Vec3 q);
int solid_edge_compare(const void *a, const void *b);
SolidCheck solid_check(const Scene *scene);
void solid_warn(const Scene *scene, FILE *f);

#endif
