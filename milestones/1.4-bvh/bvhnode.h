/* bvhnode.h: a BVH node, its two children's boxes in float, and their conservative ray test. */
#ifndef RAYTRA_BVHNODE_H
#define RAYTRA_BVHNODE_H

#include <stdbool.h>
#include <stdint.h>

#include "box.h"

/* excerpt: bvh-node */
/* Where a subtree is: an interior node, or a leaf's run of primitives. */
typedef struct {
    uint32_t index; /* interior: the node in nodes; leaf: its first entry of prims */
    uint32_t count; /* leaf: how many primitives (1 to BVH_MAX_LEAF); interior: 0 */
} BvhRef;

/* An interior node: its two children's boxes, so that one visit tests both, and where
 * the children are; 64 bytes, one cache line. Nodes are stored depth first: a first
 * child that is a node comes right after its parent. */
typedef struct {
    float bound[2][3][2]; /* child k's box spans bound[0][a][k] to bound[1][a][k] on axis
                             a, in float, rounded outwards: it holds every box below it */
    BvhRef child[2];
} BvhNode;
/* end excerpt: bvh-node */

/* A ray made ready once for bvh_node_hit: its origin in float, 1/d (grown by 2^-20 for
 * the far faces), the bound (0 or 1) it enters and leaves each slab by, the slack; each
 * number twice, once a child, so that both are tested side by side. */
typedef struct {
    float origin[3][2];
    float inv_near[3][2], inv_far[3][2];
    int near[3], far[3];
    float tmin;
    float slack;
} FloatRay;

/* Returns tmax in float, grown by 2^-20 as the far faces' t are. */
static inline float box_float_tmax(double tmax)
{
    return (float)(tmax * (1 + 0x1p-20));
}

/* Tells whether a float interval [t0, t1] may hold a t where the exact ray meets the box. */
static inline bool box_float_reaches(const FloatRay *fr, float t0, float t1)
{
    return t0 <= t1 + fr->slack;
}

/* Narrows each child k's interval [t0[k], t1[k]] to where the ray is in its slab on
 * axis a, as box_slab does (a NaN leaves them as they are); the loop over k is one
 * instruction for both children. */
static inline void node_slab(const BvhNode *node, const FloatRay *fr, int a, float t0[2],
                             float t1[2])
{
    const float *near = node->bound[fr->near[a]][a], *far = node->bound[fr->far[a]][a];
    for (int k = 0; k < 2; k++) {
        float enter = (near[k] - fr->origin[a][k]) * fr->inv_near[a][k];
        float leave = (far[k] - fr->origin[a][k]) * fr->inv_far[a][k];
        t0[k] = enter > t0[k] ? enter : t0[k];
        t1[k] = leave < t1[k] ? leave : t1[k];
    }
}

/* excerpt: bvh-node-hit */
/* Tests both children's boxes of node against the float ray fr, from fr's tmin to tmax
 * (box_float_tmax of the ray's): returns bit k set when the ray may meet child k's box,
 * and sets entry[k] to where it may enter it. Never misses a box the exact ray meets
 * (see bvhnode.c); may meet a few more. */
static inline int bvh_node_hit(const BvhNode *node, const FloatRay *fr, float tmax,
                               float entry[2])
{
    float t1[2] = {tmax, tmax};
    entry[0] = entry[1] = fr->tmin;
    node_slab(node, fr, 0, entry, t1);
    node_slab(node, fr, 1, entry, t1);
    node_slab(node, fr, 2, entry, t1);
    return box_float_reaches(fr, entry[0], t1[0]) | box_float_reaches(fr, entry[1], t1[1]) << 1;
}
/* end excerpt: bvh-node-hit */

void bvh_node_set(BvhNode *node, int k, Box box, BvhRef ref);
Box bvh_node_box(const BvhNode *node, int k);
bool box_float_in_range(Box box);
FloatRay box_float_ray(Ray r, double tmin, bool in_range);

#endif
