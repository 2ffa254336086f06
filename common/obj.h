/* obj.h: loading the triangles of a Wavefront OBJ mesh (the scene file's w command). */
#ifndef RAYTRA_OBJ_H
#define RAYTRA_OBJ_H

#include <stdbool.h>
#include <stdio.h>

#include "diag.h"
#include "vec3.h"

typedef struct {
    Vec3 *vertices;
    int vertex_count;
    int (*triangles)[3]; /* 0-based vertex indices, counterclockwise */
    int triangle_count;
} Mesh;

bool obj_load(Mesh *mesh, const char *path, Diag *diag);
bool obj_load_stream(Mesh *mesh, FILE *f, const char *path, Diag *diag);
void obj_free(Mesh *mesh);

#endif
