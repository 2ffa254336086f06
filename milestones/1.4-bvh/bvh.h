/* bvh.h: a bounding volume hierarchy over a scene's spheres and triangles, built by the SAH. */
#ifndef RAYTRA_BVH_H
#define RAYTRA_BVH_H

#include <math.h>
#include <stdbool.h>
#include <stdint.h>

#include "box.h"
#include "hit.h"
#include "ray.h"
#include "scene.h"

/* The hierarchy is never deeper than this, so a traversal stack of this size never overflows. */
#define BVH_MAX_DEPTH 64
/* Below this depth the SAH chooses splits; deeper, halving bounds the depth (grade_bvh.c). */
#define SAH_MAX_DEPTH 32
/* Leaves hold at most this many primitives. */
#define BVH_MAX_LEAF 8
/* Bins per axis of the binned SAH build. */
#define BVH_BINS 16

/* Where a subtree is: an interior node, or a leaf's run of primitives. */
typedef struct {
    uint32_t index; /* interior: the node in nodes; leaf: its first entry of prims */
    uint32_t count; /* leaf: how many primitives (1 to BVH_MAX_LEAF); interior: 0 */
} BvhRef;

/* An interior node: its two children's boxes, so that one visit tests both, and where
 * the children are. Nodes are stored depth first: a first child that is a node comes
 * right after its parent. */
typedef struct {
    double bound[2][3][2]; /* child k's box spans bound[0][a][k] to bound[1][a][k] on axis a */
    BvhRef child[2];
} BvhNode;

/* Narrows each child k's [t0[k], t1[k]] to where the ray (origin o, 1/d inv) is in its
 * slab on axis a, as box_slab does: it enters at bound 1 (hi) when it travels towards -a. */
static inline void node_slab(const BvhNode *node, int a, double o, double inv, double t0[2],
                             double t1[2])
{
    int near = signbit(inv) ? 1 : 0;
    for (int k = 0; k < 2; k++) {
        double enter = (node->bound[near][a][k] - o) * inv;
        double leave = (node->bound[1 - near][a][k] - o) * inv;
        t0[k] = enter > t0[k] ? enter : t0[k];
        t1[k] = leave < t1[k] ? leave : t1[k];
    }
}

/* Tests both children's boxes of node against ray r, from tmin to tmax, as box_hit
 * does: returns bit k set when the ray meets child k's box, and sets entry[k] to where
 * it enters it. */
static inline int bvh_node_hit(const BvhNode *node, const BoxRay *r, double tmin, double tmax,
                               double entry[2])
{
    double t1[2] = {tmax, tmax};
    entry[0] = entry[1] = tmin;
    node_slab(node, 0, r->origin.x, r->inv_dir.x, entry, t1);
    node_slab(node, 1, r->origin.y, r->inv_dir.y, entry, t1);
    node_slab(node, 2, r->origin.z, r->inv_dir.z, entry, t1);
    return (entry[0] <= t1[0]) | (entry[1] <= t1[1]) << 1;
}

/* The hierarchy. A primitive is a surface number of part 1.2's world_intersect:
 * spheres, then planes, then triangles. Planes have no box: they stay out of the
 * tree and are tested after it. */
typedef struct {
    const Scene *scene;
    Box box;        /* the root's box */
    BvhRef root;    /* a node, or a leaf when there are few primitives */
    BvhNode *nodes; /* the interior nodes; none when the root is a leaf or there is nothing */
    int node_count;
    int *prims;      /* surface numbers in leaf order: a leaf holds prims[index .. index+count) */
    int prim_count;  /* in the tree; the planes follow them in prims */
    BvhRef planes;   /* the planes, as one more run of prims: not in the tree */
    int depth;       /* levels below the root */
    Box *boxes;      /* while it is built: every surface's box, by surface number */
    Vec3 *centroids; /* while it is built: their centres */
} Bvh;

/* What a leaf does with a ray: tests its primitives, keeping what it needs in state,
 * and may lower *tmax, the farthest t still of interest. Returns true to stop there. */
typedef bool (*BvhLeafFn)(const Bvh *bvh, BvhRef leaf, Ray r, double tmin, double *tmax,
                          void *state);

void bvh_node_set(BvhNode *node, int k, Box box, BvhRef ref);
bool bvh_build(Bvh *bvh, const Scene *scene);
int bvh_split(Bvh *bvh, int begin, int end, Box box, Box centroids);
void bvh_free(Bvh *bvh);
bool bvh_traverse(const Bvh *bvh, Ray r, double tmin, double *tmax, BvhLeafFn leaf, void *state,
                  long *tests);
bool bvh_hit(const Bvh *bvh, Ray r, double tmin, double tmax, Hit *hit, long *tests);
bool bvh_blocked(const Bvh *bvh, Ray r, double tmin, double tmax);
size_t bvh_bytes(const Bvh *bvh);

#endif
