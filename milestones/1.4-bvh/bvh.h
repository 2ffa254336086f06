/* bvh.h: a bounding volume hierarchy over a scene's spheres and triangles, built by the SAH. */
#ifndef RAYTRA_BVH_H
#define RAYTRA_BVH_H

#include <stdbool.h>

#include "box.h"
#include "bvhnode.h"
#include "hit.h"
#include "ray.h"
#include "scene.h"

/* The hierarchy is never deeper than this, so a traversal stack of this size never overflows. */
#define BVH_MAX_DEPTH 64
/* Leaves hold at most this many primitives. */
#define BVH_MAX_LEAF 8
/* Bins per axis of the binned SAH build. */
#define BVH_BINS 16

/* excerpt: bvh-struct */
/* The hierarchy. A primitive is a surface number of part 1.2's world_intersect:
 * spheres, then planes, then triangles. Planes have no box: they stay out of the
 * tree and are tested after it. */
typedef struct {
    const Scene *scene;
    Box box;        /* the root's box, rounded outwards to floats as the nodes' boxes are */
    BvhRef root;    /* a node, or a leaf when there are few primitives */
    BvhNode *nodes; /* the interior nodes; none when the root is a leaf or there is nothing */
    int node_count;
    int *prims;     /* surface numbers in leaf order: a leaf holds prims[index .. index+count) */
    int prim_count; /* in the tree; the planes follow them in prims */
    BvhRef planes;  /* the planes, as one more run of prims: not in the tree */
    int leaf_count;
    int depth;     /* levels below the root */
    bool in_range; /* the float test holds for the tree's box (box_float_in_range) */
} Bvh;
/* end excerpt: bvh-struct */

/* What the build works on: every surface's box and centroid, by surface number. */
typedef struct {
    Box *boxes;
    Vec3 *centroids;
    int *prims;
    BvhNode *nodes;
    int node_count;
    int leaf_count;
    int depth;
} BvhBuilder;

/* What a leaf does with a ray: tests its primitives, keeping what it needs in state,
 * and may lower *tmax, the farthest t still of interest. Returns true to stop there. */
typedef bool (*BvhLeafFn)(const Bvh *bvh, BvhRef leaf, Ray r, double tmin, double *tmax,
                          void *state);

bool bvh_build(Bvh *bvh, const Scene *scene);
int bvh_split(BvhBuilder *b, int begin, int end, Box box, Box centroids);
void bvh_free(Bvh *bvh);
bool bvh_traverse(const Bvh *bvh, Ray r, double tmin, double *tmax, BvhLeafFn leaf, void *state,
                  long *tests);
bool bvh_hit(const Bvh *bvh, Ray r, double tmin, double tmax, Hit *hit);
bool bvh_blocked(const Bvh *bvh, Ray r, double tmin, double tmax);
size_t bvh_bytes(const Bvh *bvh);
long bvh_count_tests(const Bvh *bvh, Ray r);

#endif
