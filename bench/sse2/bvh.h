/* bench/sse2/bvh.h: the SSE2 experiment's BVH (bench/sse2/bvh.c), as part 1.4 had it. */
#ifndef RAYTRA_BVH_H
#define RAYTRA_BVH_H

#include <stdbool.h>
#include <stdint.h>

#include "box.h"
#include "hit.h"
#include "ray.h"
#include "scene.h"

/* The hierarchy is never deeper than this, so a traversal stack of this size never overflows. */
#define BVH_MAX_DEPTH 64
/* Leaves hold at most this many primitives. */
#define BVH_MAX_LEAF 8
/* Bins per axis of the binned SAH build. */
#define BVH_BINS 16

/* excerpt: bvh-node */
/* Where a subtree is: an interior node, or a leaf's run of primitives. */
typedef struct {
    uint32_t index; /* interior: the node in nodes; leaf: its first entry of prims */
    uint32_t count; /* leaf: how many primitives (1 to BVH_MAX_LEAF); interior: 0 */
} BvhRef;

/* An interior node of the flattened hierarchy: its two children's boxes side by side,
 * so that one cache line of 64 bytes answers for both, and where the children are.
 * Nodes are stored depth first: an interior first child comes right after its parent. */
typedef struct {
    float bounds[3][4]; /* on axis a: child 0's lo, child 1's lo, child 0's hi, child 1's hi,
                           rounded outwards so that each holds every double box below it */
    uint32_t index[2];  /* child k: its node, or its leaf's first entry of prims */
    uint16_t count[2];  /* child k: 0 for a node, or its leaf's number of primitives */
    uint8_t axis;       /* the axis the children were split along */
    uint8_t unused[3];
} BvhNode;
/* end excerpt: bvh-node */

/* excerpt: bvh-struct */
/* The hierarchy. A primitive is named by one number: sphere k is k, triangle k is
 * sphere_count + k. Ordering by this number is ordering by (kind, index) as part 1.2's
 * world_hit tests them, which is how ties are broken. Planes have no box: they stay out. */
typedef struct {
    const Scene *scene;
    Box box;         /* the root's box, rounded outwards to floats */
    BvhRef root;     /* a node, or a leaf when there are few primitives */
    BvhNode *nodes;  /* the interior nodes; none when the root is a leaf or there is nothing */
    int node_count;
    uint32_t *prims; /* the primitives in leaf order: a leaf holds prims[index .. index+count) */
    int prim_count;
    int leaf_count;
    int depth; /* levels below the root */
    bool float_safe; /* every coordinate of the box is small enough for the float test */
} Bvh;
/* end excerpt: bvh-struct */

bool bvh_build(Bvh *bvh, const Scene *scene);
void bvh_free(Bvh *bvh);
Box bvh_child_box(const BvhNode *node, int k);
BvhRef bvh_child(const BvhNode *node, int k);
void bvh_node_set_child(BvhNode *node, int k, Box box, BvhRef ref);
Box bvh_prim_box(const Scene *scene, uint32_t prim);
void bvh_prim_surface(const Scene *scene, uint32_t prim, Hit *hit);
bool bvh_hit(const Bvh *bvh, Ray r, double tmin, double tmax, Hit *hit);
bool bvh_blocked(const Bvh *bvh, Ray r, double tmin, double tmax);
bool bvh_hit_leaf_boxes(const Bvh *bvh, Ray r, double tmin, double tmax, Hit *hit);
size_t bvh_bytes(const Bvh *bvh);
long bvh_count_tests(const Bvh *bvh, Ray r);
int bvh_children_hit(const Bvh *bvh, const BvhNode *node, Ray r, double tmin, double tmax);

#endif
