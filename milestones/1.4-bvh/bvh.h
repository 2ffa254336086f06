/* bvh.h: a bounding volume hierarchy over a scene's spheres and triangles, built by the SAH. */
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
/* A node of the flattened hierarchy: 32 bytes, two to a 64-byte cache line. Nodes are
 * stored depth first: an interior node's first child comes right after it. */
typedef struct {
    float lo[3], hi[3]; /* its box in float, rounded outwards so that it holds every
                           double box below it: no hit is ever lost to rounding */
    uint32_t index;     /* interior: its second child; leaf: its first entry of prims */
    uint16_t count;     /* leaf: how many primitives (1 to BVH_MAX_LEAF); interior: 0 */
    uint8_t axis;       /* interior: the axis its children were split along */
    uint8_t unused;
} BvhNode;
/* end excerpt: bvh-node */

/* excerpt: bvh-struct */
/* The hierarchy. A primitive is named by one number: sphere k is k, triangle k is
 * sphere_count + k. Ordering by this number is ordering by (kind, index) as part 1.2's
 * world_hit tests them, which is how ties are broken. Planes have no box: they stay out. */
typedef struct {
    const Scene *scene;
    BvhNode *nodes; /* node 0 is the root; none when there are no primitives */
    int node_count;
    uint32_t *prims; /* the primitives in leaf order: leaf n holds prims[index .. index+count) */
    int prim_count;
    int leaf_count;
    int depth; /* levels below the root */
} Bvh;
/* end excerpt: bvh-struct */

bool bvh_build(Bvh *bvh, const Scene *scene);
void bvh_free(Bvh *bvh);
Box bvh_node_box(const BvhNode *node);
Box bvh_prim_box(const Scene *scene, uint32_t prim);
void bvh_prim_surface(const Scene *scene, uint32_t prim, Hit *hit);
bool bvh_hit(const Bvh *bvh, Ray r, double tmin, double tmax, Hit *hit);
bool bvh_blocked(const Bvh *bvh, Ray r, double tmin, double tmax);
bool bvh_hit_leaf_boxes(const Bvh *bvh, Ray r, double tmin, double tmax, Hit *hit);
size_t bvh_bytes(const Bvh *bvh);

#endif
