/* bvh.c: building a bounding volume hierarchy by the binned SAH, and tracing rays through it. */
#include "bvh.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>

#include "sphere.h"
#include "triangle.h"

/* The SAH's costs: of visiting a node (two box tests), and of testing one primitive. */
#define COST_TRAVERSE 1.0
#define COST_INTERSECT 1.0
/* Below this depth the SAH chooses splits; deeper, halving the primitives bounds the depth. */
#define SAH_MAX_DEPTH 32

/* Returns the box of primitive prim of scene: its sphere's or its triangle's. */
Box bvh_prim_box(const Scene *scene, uint32_t prim)
{
    if (prim < (uint32_t)scene->sphere_count)
        return box_of_sphere(&scene->spheres[prim]);
    return box_of_triangle(&scene->triangles[prim - (uint32_t)scene->sphere_count]);
}

/* Returns the float just below x, or x itself when it is one: never above x. */
static float float_below(double x)
{
    if (x >= FLT_MAX)
        return FLT_MAX;
    if (x < -FLT_MAX)
        return -INFINITY;
    float f = (float)x;
    return (double)f > x ? nextafterf(f, -INFINITY) : f;
}

/* Returns the float just above x, or x itself when it is one: never below x. */
static float float_above(double x)
{
    return -float_below(-x);
}

/* Returns the box of node in double: exactly its float box. */
static inline Box node_box(const BvhNode *node)
{
    return (Box){vec3(node->lo[0], node->lo[1], node->lo[2]),
                 vec3(node->hi[0], node->hi[1], node->hi[2])};
}

/* Returns the box of node, as the traversal tests it. */
Box bvh_node_box(const BvhNode *node)
{
    return node_box(node);
}

/* What the build works on: every primitive's box and centroid, by primitive number. */
typedef struct {
    Box *boxes;
    Vec3 *centroids;
    uint32_t *prims;
    BvhNode *nodes;
    int node_count;
    int leaf_count;
    int depth;
} Builder;

/* Returns coordinate axis of v. */
static inline double axis_of(Vec3 v, int axis)
{
    return axis == 0 ? v.x : axis == 1 ? v.y : v.z;
}

/* Returns the bin of centroid coordinate c, for bins of width 1 / scale from lo. */
static inline int bin_of(double c, double lo, double scale)
{
    int b = (int)((c - lo) * scale);
    return b < 0 ? 0 : b >= BVH_BINS ? BVH_BINS - 1 : b;
}

/* excerpt: bvh-sah */
/* Chooses where to split prims[begin, end) by the surface area heuristic: a ray that
 * meets a box of area A meets a child box of area A' inside it with probability about
 * A'/A, so a split into (A_L, N_L) and (A_R, N_R) costs, per ray reaching the node,
 *     C_traverse + (A_L N_L + A_R N_R) / A * C_intersect,
 * against N C_intersect for testing every primitive in a leaf. The candidates are the
 * 15 planes between BVH_BINS equal bins of the centroids, on each axis. Reorders the
 * primitives so that the left child's come first and returns the first of the right
 * child's, with *axis; or -1 when no split is cheaper than a leaf. */
static int sah_split(Builder *b, int begin, int end, Box box, Box centroids, int *axis)
{
    double area = box_half_area(box);
    if (!(area > 0))
        return -1; /* a point or a line: every split looks free, the SAH cannot choose */
    int n = end - begin;
    /* The bins of the three axes are filled in one pass over the primitives. */
    double lo[3], scale[3];
    Box bin_box[3][BVH_BINS];
    int bin_count[3][BVH_BINS] = {{0}};
    for (int a = 0; a < 3; a++) {
        lo[a] = axis_of(centroids.lo, a);
        double extent = axis_of(centroids.hi, a) - lo[a];
        /* Every centroid on one plane: nothing to split along this axis. */
        scale[a] = extent > 0 ? BVH_BINS / extent : 0;
        for (int k = 0; k < BVH_BINS; k++)
            bin_box[a][k] = box_empty();
    }
    for (int k = begin; k < end; k++) {
        uint32_t p = b->prims[k];
        Vec3 c = b->centroids[p];
        Box pb = b->boxes[p];
        for (int a = 0; a < 3; a++) {
            int bin = bin_of(axis_of(c, a), lo[a], scale[a]);
            bin_box[a][bin] = box_union(bin_box[a][bin], pb);
            bin_count[a][bin]++;
        }
    }
    double best_cost = n * COST_INTERSECT;
    int best_axis = -1, best_bin = 0;
    for (int a = 0; a < 3; a++) {
        if (scale[a] == 0)
            continue;
        /* One sweep from the right gathers A_R N_R for each plane, one from the left A_L N_L. */
        double right_cost[BVH_BINS];
        Box right = box_empty();
        int right_n = 0;
        for (int k = BVH_BINS - 1; k > 0; k--) {
            right = box_union(right, bin_box[a][k]);
            right_n += bin_count[a][k];
            right_cost[k] = box_half_area(right) * right_n;
        }
        Box left = box_empty();
        int left_n = 0;
        for (int k = 1; k < BVH_BINS; k++) {
            left = box_union(left, bin_box[a][k - 1]);
            left_n += bin_count[a][k - 1];
            if (left_n == 0 || left_n == n)
                continue;
            double cost = COST_TRAVERSE +
                          (box_half_area(left) * left_n + right_cost[k]) / area * COST_INTERSECT;
            if (cost < best_cost) {
                best_cost = cost;
                best_axis = a;
                best_bin = k;
            }
        }
    }
    if (best_axis < 0)
        return -1;
    /* Partition in place: primitives of bins below best_bin to the front. */
    int i = begin, j = end - 1;
    while (i <= j) {
        if (bin_of(axis_of(b->centroids[b->prims[i]], best_axis), lo[best_axis],
                   scale[best_axis]) < best_bin) {
            i++;
        } else {
            uint32_t swap = b->prims[i];
            b->prims[i] = b->prims[j];
            b->prims[j--] = swap;
        }
    }
    *axis = best_axis;
    return i;
}
/* end excerpt: bvh-sah */

/* Returns the axis along which box b is longest. */
static int longest_axis(Box b)
{
    Vec3 e = vec3_sub(b.hi, b.lo);
    return e.x >= e.y && e.x >= e.z ? 0 : e.y >= e.z ? 1 : 2;
}

/* excerpt: bvh-build-node */
/* Builds the subtree over prims[begin, end) at the given depth, depth first into
 * b->nodes, and returns the index of its root. */
static uint32_t build_node(Builder *b, int begin, int end, int depth)
{
    uint32_t self = (uint32_t)b->node_count++;
    Box box = box_empty(), centroids = box_empty();
    for (int k = begin; k < end; k++) {
        box = box_union(box, b->boxes[b->prims[k]]);
        centroids = box_add_point(centroids, b->centroids[b->prims[k]]);
    }
    /* Rounding the box outwards to floats keeps every primitive's box inside it. */
    BvhNode *node = &b->nodes[self];
    *node = (BvhNode){.lo = {float_below(box.lo.x), float_below(box.lo.y), float_below(box.lo.z)},
                      .hi = {float_above(box.hi.x), float_above(box.hi.y), float_above(box.hi.z)}};
    if (depth > b->depth)
        b->depth = depth;

    int n = end - begin, axis = 0, mid = -1;
    if (n > 1 && depth < SAH_MAX_DEPTH)
        mid = sah_split(b, begin, end, box, centroids, &axis);
    /* When the SAH finds no split (all centroids equal, or too deep) but the leaf would
     * be too big, halve the primitives as they are: any split beats none. */
    if (mid < 0 && n > BVH_MAX_LEAF) {
        mid = begin + n / 2;
        axis = longest_axis(centroids);
    }
    if (mid < 0) {
        node->index = (uint32_t)begin;
        node->count = (uint16_t)n;
        b->leaf_count++;
        return self;
    }
    node->axis = (uint8_t)axis;
    build_node(b, begin, mid, depth + 1); /* the first child is node self + 1 */
    uint32_t second = build_node(b, mid, end, depth + 1);
    node->index = second;
    return self;
}
/* end excerpt: bvh-build-node */

/* Builds the hierarchy of scene's spheres and triangles; false when out of memory. */
bool bvh_build(Bvh *bvh, const Scene *scene)
{
    *bvh = (Bvh){.scene = scene};
    int n = scene->sphere_count + scene->triangle_count;
    if (n == 0)
        return true;
    Builder b = {.boxes = malloc((size_t)n * sizeof *b.boxes),
                 .centroids = malloc((size_t)n * sizeof *b.centroids),
                 .prims = malloc((size_t)n * sizeof *b.prims),
                 .nodes = malloc((size_t)(2 * n - 1) * sizeof *b.nodes)};
    bool ok = b.boxes != NULL && b.centroids != NULL && b.prims != NULL && b.nodes != NULL;
    if (ok) {
        for (int k = 0; k < n; k++) {
            b.prims[k] = (uint32_t)k;
            b.boxes[k] = bvh_prim_box(scene, (uint32_t)k);
            b.centroids[k] = box_center(b.boxes[k]);
        }
        build_node(&b, 0, n, 0);
        /* A binary tree whose leaves hold at least one primitive has at most 2n - 1 nodes. */
        BvhNode *fit = realloc(b.nodes, (size_t)b.node_count * sizeof *b.nodes);
        bvh->nodes = fit != NULL ? fit : b.nodes;
        bvh->node_count = b.node_count;
        bvh->prims = b.prims;
        bvh->prim_count = n;
        bvh->leaf_count = b.leaf_count;
        bvh->depth = b.depth;
    } else {
        free(b.prims);
        free(b.nodes);
    }
    free(b.boxes);
    free(b.centroids);
    return ok;
}

/* Frees what bvh_build allocated. */
void bvh_free(Bvh *bvh)
{
    free(bvh->nodes);
    free(bvh->prims);
    *bvh = (Bvh){0};
}

/* Returns the memory the hierarchy takes beyond the scene: nodes and primitive numbers. */
size_t bvh_bytes(const Bvh *bvh)
{
    return (size_t)bvh->node_count * sizeof *bvh->nodes +
           (size_t)bvh->prim_count * sizeof *bvh->prims;
}

/* What a leaf does with a ray: tests its primitives, keeping what it needs in state,
 * and may lower *tmax, the farthest t still of interest. Returns true to stop there. */
typedef bool (*LeafFn)(const Bvh *bvh, const BvhNode *leaf, Ray r, double tmin, double *tmax,
                       void *state);

/* An entry of the traversal stack: a node still to visit and where the ray enters its box. */
typedef struct {
    uint32_t node;
    double t;
} Pending;

/* The traversal is written once and inlined into each of its three users, where the leaf
 * function becomes a direct call the compiler can inline too. */
#if defined(__GNUC__)
#define ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define ALWAYS_INLINE inline
#endif

/* excerpt: bvh-traverse */
/* Visits every leaf whose box ray r meets with tmin <= t <= *tmax, nearer boxes first,
 * calling leaf for each, without recursion. Returns true when leaf asked to stop. */
static ALWAYS_INLINE bool traverse(const Bvh *bvh, Ray r, double tmin, double *tmax, LeafFn leaf,
                            void *state)
{
    if (bvh->node_count == 0)
        return false;
    const BvhNode *nodes = bvh->nodes;
    BoxRay br = box_ray(r);
    bool negative[3] = {signbit(r.dir.x), signbit(r.dir.y), signbit(r.dir.z)};
    Pending stack[BVH_MAX_DEPTH];
    int top = 0;
    double t;
    if (!box_hit(node_box(&nodes[0]), &br, tmin, *tmax, &t))
        return false;
    uint32_t current = 0;
    for (;;) {
        const BvhNode *node = &nodes[current];
        if (node->count > 0) {
            if (leaf(bvh, node, r, tmin, tmax, state))
                return true;
        } else {
            /* Both children's boxes are tested; the ray goes on into the nearer one
             * and the other waits on the stack. When the ray starts inside both (the
             * entry is tmin for each), the split axis decides: the child on the side
             * the ray comes from first. */
            uint32_t near = current + 1, far = node->index;
            if (negative[node->axis]) {
                near = node->index;
                far = current + 1;
            }
            double t_near, t_far;
            bool hit_near = box_hit(node_box(&nodes[near]), &br, tmin, *tmax, &t_near);
            bool hit_far = box_hit(node_box(&nodes[far]), &br, tmin, *tmax, &t_far);
            if (hit_near && hit_far) {
                if (t_far < t_near) {
                    uint32_t swap = near;
                    near = far;
                    far = swap;
                    t_far = t_near;
                }
                stack[top++] = (Pending){far, t_far};
                current = near;
                continue;
            }
            if (hit_near || hit_far) {
                current = hit_near ? near : far;
                continue;
            }
        }
        /* Back up to the nearest waiting node that a hit found since has not ruled out. */
        do {
            if (top == 0)
                return false;
            top--;
        } while (stack[top].t > *tmax);
        current = stack[top].node;
    }
}
/* end excerpt: bvh-traverse */

/* Finds where ray r meets primitive prim with tmin < t < tmax. */
static inline bool prim_intersect(const Scene *scene, uint32_t prim, Ray r, double tmin,
                                  double tmax, double *t)
{
    if (prim < (uint32_t)scene->sphere_count)
        return sphere_intersect(&scene->spheres[prim], r, tmin, tmax, t);
    TriangleHit th;
    if (!triangle_intersect(&scene->triangles[prim - (uint32_t)scene->sphere_count], r, tmin,
                            tmax, &th))
        return false;
    *t = th.t;
    return true;
}

/* The closest hit so far: the primitive (or leaf node) and its t. */
typedef struct {
    bool found;
    uint32_t which;
    double t;
    double limit; /* tests accept t < limit: tmax at first, then just above t for ties */
} Closest;

/* Records a hit at t of which when it beats the closest so far: nearer, or as near
 * and first in the order of part 1.2's world_hit. Lowers *tmax to t. Tells whether it did. */
static inline bool closest_offer(Closest *c, uint32_t which, double t, double *tmax)
{
    if (c->found && !(t < c->t || (t == c->t && which < c->which)))
        return false;
    *c = (Closest){true, which, t, nextafter(t, INFINITY)};
    *tmax = t;
    return true;
}

/* excerpt: bvh-leaf-closest */
/* Tests a leaf's primitives for the closest hit. A primitive tested with t < limit,
 * just above the closest t, also finds hits at exactly that t: of several surfaces
 * at the same t, brute force keeps the first it tested, and so must we. */
static bool leaf_closest(const Bvh *bvh, const BvhNode *leaf, Ray r, double tmin, double *tmax,
                         void *state)
{
    Closest *c = state;
    for (uint32_t k = leaf->index; k < leaf->index + leaf->count; k++) {
        double t;
        if (prim_intersect(bvh->scene, bvh->prims[k], r, tmin, c->limit, &t))
            closest_offer(c, bvh->prims[k], t, tmax);
    }
    return false;
}
/* end excerpt: bvh-leaf-closest */

/* Fills in the kind, index and material of primitive prim of scene in hit. */
void bvh_prim_surface(const Scene *scene, uint32_t prim, Hit *hit)
{
    if (prim < (uint32_t)scene->sphere_count) {
        hit->kind = SURFACE_SPHERE;
        hit->index = (int)prim;
        hit->material = scene->spheres[prim].material;
    } else {
        hit->kind = SURFACE_TRIANGLE;
        hit->index = (int)(prim - (uint32_t)scene->sphere_count);
        hit->material = scene->triangles[hit->index].material;
    }
}

/* Finds the closest sphere or triangle ray r meets with tmin < t < tmax, as part 1.2's
 * world_hit would among them; sets only hit's t, kind, index and material. */
bool bvh_hit(const Bvh *bvh, Ray r, double tmin, double tmax, Hit *hit)
{
    Closest c = {.limit = tmax};
    traverse(bvh, r, tmin, &tmax, leaf_closest, &c);
    if (!c.found)
        return false;
    *hit = (Hit){.t = c.t};
    bvh_prim_surface(bvh->scene, c.which, hit);
    return true;
}

/* excerpt: bvh-leaf-any */
/* Tests a leaf's primitives for any hit at all: the first one found stops the traversal. */
static bool leaf_any(const Bvh *bvh, const BvhNode *leaf, Ray r, double tmin, double *tmax,
                     void *state)
{
    (void)state;
    for (uint32_t k = leaf->index; k < leaf->index + leaf->count; k++) {
        double t;
        if (prim_intersect(bvh->scene, bvh->prims[k], r, tmin, *tmax, &t))
            return true;
    }
    return false;
}
/* end excerpt: bvh-leaf-any */

/* Tells whether any sphere or triangle lies on ray r with tmin < t < tmax. */
bool bvh_blocked(const Bvh *bvh, Ray r, double tmin, double tmax)
{
    return traverse(bvh, r, tmin, &tmax, leaf_any, NULL);
}

/* The closest leaf box so far, and where the ray meets it. */
typedef struct {
    Closest closest;
    BoxHit face;
} LeafBoxes;

/* Tests a leaf's own box, as if it were a surface: mode 2 draws the leaves. */
static bool leaf_box(const Bvh *bvh, const BvhNode *leaf, Ray r, double tmin, double *tmax,
                     void *state)
{
    LeafBoxes *lb = state;
    BoxHit face;
    if (box_hit_face(node_box(leaf), r, tmin, lb->closest.limit, &face) &&
        closest_offer(&lb->closest, (uint32_t)(leaf - bvh->nodes), face.t, tmax))
        lb->face = face;
    return false;
}

/* Finds the closest leaf box that ray r meets with tmin < t < tmax, as a surface with
 * one of the six axis normals (facing the ray) and the material of the leaf's first
 * primitive; fills in all of hit. */
bool bvh_hit_leaf_boxes(const Bvh *bvh, Ray r, double tmin, double tmax, Hit *hit)
{
    LeafBoxes lb = {.closest = {.limit = tmax}};
    traverse(bvh, r, tmin, &tmax, leaf_box, &lb);
    if (!lb.closest.found)
        return false;
    const BvhNode *leaf = &bvh->nodes[lb.closest.which];
    *hit = (Hit){.t = lb.face.t, .point = ray_at(r, lb.face.t), .normal = box_face_normal(&lb.face)};
    bvh_prim_surface(bvh->scene, bvh->prims[leaf->index], hit);
    return true;
}
