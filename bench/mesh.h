/* mesh.h: the benchmark's meshes: OBJ files loaded and timed, and geodesic spheres. */
#ifndef RAYTRA_BENCH_MESH_H
#define RAYTRA_BENCH_MESH_H

#include <stdbool.h>

#include "box.h"
#include "scene.h"

/* A benchmark mesh: its triangles as a scene, and how it was obtained. */
typedef struct {
    const char *name;
    Scene scene;
    double load_mb_per_s; /* the OBJ reader's speed; 0 for a generated mesh */
} BenchMesh;

bool mesh_load(BenchMesh *m, const char *name, const char *path);
void mesh_sphere(BenchMesh *m, const char *name, int level);
Box mesh_box(const Scene *scene);

#endif
