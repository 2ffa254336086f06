/* bench/sse2/bvh.c: part 1.4's BVH as it was before it was written for students: a node's two float boxes tested together with SSE2 (make -C bench run-sse2). */
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

/* Returns the number of the triangle that primitive prim of scene is, when not a sphere. */
static inline int prim_triangle(const Scene *scene, uint32_t prim)
{
    return (int)(prim - (uint32_t)scene->sphere_count);
}

/* Returns the box of primitive prim of scene: its sphere's or its triangle's. */
Box bvh_prim_box(const Scene *scene, uint32_t prim)
{
    if (prim < (uint32_t)scene->sphere_count)
        return box_of_sphere(&scene->spheres[prim]);
    Triangle tri = scene_triangle(scene, prim_triangle(scene, prim));
    return box_of_triangle(&tri);
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

_Static_assert(sizeof(BvhNode) == 64, "a node is one cache line");

/* Returns the box of child k of node in double: exactly its float box. */
Box bvh_child_box(const BvhNode *node, int k)
{
    return (Box){vec3(node->bounds[0][k], node->bounds[1][k], node->bounds[2][k]),
                 vec3(node->bounds[0][2 + k], node->bounds[1][2 + k], node->bounds[2][2 + k])};
}

/* Returns where child k of node is. */
BvhRef bvh_child(const BvhNode *node, int k)
{
    return (BvhRef){node->index[k], node->count[k]};
}

/* Returns box b rounded outwards to floats: the float box that holds it. */
static Box box_to_floats(Box b)
{
    return (Box){vec3(float_below(b.lo.x), float_below(b.lo.y), float_below(b.lo.z)),
                 vec3(float_above(b.hi.x), float_above(b.hi.y), float_above(b.hi.z))};
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

/* Stores child k of node: where it is, and its box rounded outwards to floats, which
 * keeps every primitive's box inside it. */
void bvh_node_set_child(BvhNode *node, int k, Box box, BvhRef ref)
{
    Box f = box_to_floats(box);
    for (int a = 0; a < 3; a++) {
        node->bounds[a][k] = (float)axis_of(f.lo, a);
        node->bounds[a][2 + k] = (float)axis_of(f.hi, a);
    }
    node->index[k] = ref.index;
    node->count[k] = (uint16_t)ref.count;
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
        if (bin_of(axis_of(b->centroids[b->prims[i]], best_axis), lo[best_axis], scale[best_axis]) <
            best_bin) {
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
 * b->nodes; returns where it is, and its box in *box_out. */
static BvhRef build_node(Builder *b, int begin, int end, int depth, Box *box_out)
{
    Box box = box_empty(), centroids = box_empty();
    for (int k = begin; k < end; k++) {
        box = box_union(box, b->boxes[b->prims[k]]);
        centroids = box_add_point(centroids, b->centroids[b->prims[k]]);
    }
    *box_out = box;
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
        b->leaf_count++;
        return (BvhRef){(uint32_t)begin, (uint32_t)n};
    }
    uint32_t self = (uint32_t)b->node_count++;
    BvhRef child[2];
    Box child_box[2];
    child[0] = build_node(b, begin, mid, depth + 1, &child_box[0]); /* node self + 1 */
    child[1] = build_node(b, mid, end, depth + 1, &child_box[1]);
    BvhNode *node = &b->nodes[self];
    *node = (BvhNode){.axis = (uint8_t)axis};
    for (int k = 0; k < 2; k++)
        bvh_node_set_child(node, k, child_box[k], child[k]);
    return (BvhRef){self, 0};
}
/* end excerpt: bvh-build-node */

/* Tells whether every coordinate of box b lies within +-2^60: then no t the float test
 * computes can overflow (see float_ray). */
static bool box_float_safe(Box b)
{
    return vec3_max_abs(b.lo) <= 0x1p60 && vec3_max_abs(b.hi) <= 0x1p60;
}

/* Builds the hierarchy of scene's spheres and triangles; false when out of memory. */
bool bvh_build(Bvh *bvh, const Scene *scene)
{
    *bvh = (Bvh){.scene = scene};
    int n = scene->sphere_count + scene->triangle_count;
    if (n == 0)
        return true;
    /* A binary tree of n leaves or fewer has at most n - 1 interior nodes. */
    Builder b = {.boxes = malloc((size_t)n * sizeof *b.boxes),
                 .centroids = malloc((size_t)n * sizeof *b.centroids),
                 .prims = malloc((size_t)n * sizeof *b.prims),
                 .nodes = malloc((size_t)(n > 1 ? n - 1 : 1) * sizeof *b.nodes)};
    bool ok = b.boxes != NULL && b.centroids != NULL && b.prims != NULL && b.nodes != NULL;
    if (ok) {
        for (int k = 0; k < n; k++) {
            b.prims[k] = (uint32_t)k;
            b.boxes[k] = bvh_prim_box(scene, (uint32_t)k);
            b.centroids[k] = box_center(b.boxes[k]);
        }
        Box box;
        bvh->root = build_node(&b, 0, n, 0, &box);
        bvh->box = box_to_floats(box);
        bvh->float_safe = box_float_safe(bvh->box);
        BvhNode *fit = realloc(b.nodes, (size_t)(b.node_count > 0 ? b.node_count : 1) * sizeof *b.nodes);
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

/* excerpt: bvh-float-ray */
/* Four floats: the traversal tests a node's two boxes, near and far planes, at once.
 * With SSE2 (every x86-64 processor) they are one register; elsewhere, or when built
 * with -DBVH_PORTABLE (the tests build it so too), an array and plain C. */
#if defined(__SSE2__) && !defined(BVH_PORTABLE)
#define BVH_SSE2
#endif
#ifdef BVH_SSE2
#include <emmintrin.h>
typedef __m128 Float4;
#else
typedef struct {
    float v[4];
} Float4;
#endif

/* A ray made ready for the float test of a node's two boxes. On axis a it meets the
 * planes of child k's near face at t = (near - o) / d and of its far face at
 * t = (far - o) / d; the near face is lo when d >= 0, hi when d < 0. The four lanes
 * are the near faces of children 0 and 1, then their far faces, which are negated
 * so that one max gathers both ends of the intervals (the max of -far is -min far). */
typedef struct {
    int near[3], far[3]; /* where on axis a the near and far faces are in bounds[0]:
                            4 a for lo, 4 a + 2 for hi */
    Float4 origin[3];    /* the origin on axis a rounded to float; when d = 0 on that
                            axis, down in the near lanes and up in the far ones */
    Float4 inv_dir[3];   /* 1/d on axis a, negated in the far lanes, and times
                            1 - epsilon in the near lanes, 1 + epsilon in the far ones */
    Float4 slack;        /* how far the origin's rounding may move a t: see float_ray */
    Float4 slack2;       /* twice the slack: how far enter + -leave may exceed 0 */
    float tmin;          /* the ray's tmin, rounded down */
} SseRay;
/* end excerpt: bvh-float-ray */

/* The relative error allowed for every t computed in float: 2^-20 covers its three
 * float roundings (of 1/d times 1 -+ epsilon, of face - o, of the product; 2^-24 each)
 * and the two in double, with room to spare. */
#define FLOAT_TEST_EPSILON 0x1p-20f

/* Returns the larger of a and b, or b when either is NaN, as SSE's max does. */
static inline float float_max(float a, float b)
{
    return a > b ? a : b;
}

/* Returns four floats: a, b, c and d. */
static inline Float4 float4(float a, float b, float c, float d)
{
#ifdef BVH_SSE2
    return _mm_setr_ps(a, b, c, d);
#else
    return (Float4){{a, b, c, d}};
#endif
}

/* excerpt: bvh-float-ray-make */
/* Makes ray r ready for the float test, once a ray: 1/d, the faces' order, and how far
 * a t computed in float may be from the exact one. Its roundings (see
 * FLOAT_TEST_EPSILON) move t by less than 4 parts in 2^24 of itself, which the factor
 * 1 - epsilon in the near lanes more than undoes, and 1 + epsilon in the far lanes,
 * negated, likewise; rounding the origin to float moves t by (o - o_float) / d, the
 * slack. So no entry comes out later than the exact one plus the slack (an entry
 * below 0, pulled towards 0, stays below the slack, and the max with tmin >= 0
 * outweighs it), and no -exit larger than the exact one plus the slack (an exit just
 * below 0 too, once the slack is grown by 2^-16). FLT_MIN covers t so small that
 * their floats have fewer than 24 digits.
 * A zero component of d makes that slab a test of the origin alone: 1/d = +inf, the
 * near face is lo and the far one hi, and the origin is rounded down for lo and up for
 * hi, so that (lo - o) * inf and (hi - o) * inf say "outside" only when it is so. */
static SseRay float_ray(const Bvh *bvh, Ray r, const BoxRay *br, double tmin)
{
    SseRay fr;
    fr.tmin = float_below(tmin);
    double o[3] = {r.origin.x, r.origin.y, r.origin.z}, d[3] = {r.dir.x, r.dir.y, r.dir.z};
    double inv_d[3] = {br->inv_dir.x, br->inv_dir.y, br->inv_dir.z};
    /* The largest slack and |o| of the three axes, and whether every 1/d is in range. */
    double slack = 0, o_max = 0;
    bool safe = bvh->float_safe && tmin >= 0;
    for (int a = 0; a < 3; a++) {
        int hi_first = d[a] < 0 ? 2 : 0;
        fr.near[a] = 4 * a + hi_first;
        fr.far[a] = 4 * a + 2 - hi_first;
        double o_abs = fabs(o[a]);
        o_max = o_abs > o_max ? o_abs : o_max;
        if (d[a] == 0) {
            float below = float_below(o[a]), above = float_above(o[a]);
            fr.origin[a] = float4(below, below, above, above);
            fr.inv_dir[a] = float4(INFINITY, INFINITY, -INFINITY, -INFINITY);
            continue;
        }
        float of = (float)o[a];
        float enter = (float)(inv_d[a] * (1 - FLOAT_TEST_EPSILON));
        float leave = (float)(inv_d[a] * (1 + FLOAT_TEST_EPSILON));
        fr.origin[a] = float4(of, of, of, of);
        fr.inv_dir[a] = float4(enter, enter, -leave, -leave);
        double inv_abs = fabs(inv_d[a]), shift = fabs(o[a] - of) * inv_abs;
        slack = shift > slack ? shift : slack;
        safe = safe && inv_abs >= 0x1p-50 && inv_abs <= 0x1p50;
    }
    if (!safe || !(o_max <= 0x1p50)) {
        /* Past these bounds a float could overflow or lose all its digits: an infinite
         * slack makes the test meet every box, which is slow but never wrong. */
        for (int a = 0; a < 3; a++)
            fr.origin[a] = fr.inv_dir[a] = float4(0, 0, 0, 0);
        fr.slack = fr.slack2 = float4(INFINITY, INFINITY, INFINITY, INFINITY);
        return fr;
    }
    float s = float_above(slack * (1 + 0x1p-16) + FLT_MIN);
    fr.slack = float4(s, s, s, s);
    fr.slack2 = float4(2 * s, 2 * s, 2 * s, 2 * s);
    return fr;
}
/* end excerpt: bvh-float-ray-make */

/* excerpt: bvh-node-hit */
/* Returns the four lanes' t where the float ray fr meets a node's planes on axis a:
 * child 0's and child 1's near face, then their far faces, negated. */
static inline Float4 slab_lanes(const float *bounds, const SseRay *fr, int a)
{
#ifdef BVH_SSE2
    __m128 faces = _mm_loadl_pi(_mm_setzero_ps(), (const __m64 *)(bounds + fr->near[a]));
    faces = _mm_loadh_pi(faces, (const __m64 *)(bounds + fr->far[a]));
    return _mm_mul_ps(_mm_sub_ps(faces, fr->origin[a]), fr->inv_dir[a]);
#else
    Float4 t;
    for (int k = 0; k < 4; k++) {
        float face = bounds[(k < 2 ? fr->near[a] : fr->far[a]) + k % 2];
        t.v[k] = (face - fr->origin[a].v[k]) * fr->inv_dir[a].v[k];
    }
    return t;
#endif
}

/* Returns the larger of a and b in each lane, or b's lane where a's is NaN. */
static inline Float4 float4_max(Float4 a, Float4 b)
{
#ifdef BVH_SSE2
    return _mm_max_ps(a, b);
#else
    for (int k = 0; k < 4; k++)
        a.v[k] = float_max(a.v[k], b.v[k]);
    return a;
#endif
}

/* Tests both children's boxes of node against the float ray fr, whose limits are
 * [tmin, tmin, -tmax, -tmax]: returns bit k set when the ray may meet child k's box.
 * Conservative: it may meet a box the ray misses, never the reverse. *lanes gets
 * [enter 0, enter 1, -leave 0, -leave 1], the max of the three slabs' lanes and the
 * limits, taken as a tree so that the two first maxes run side by side. Each lane may
 * be off by the slack (see float_ray), so child k is met when enter k - leave k is at
 * most twice the slack. A NaN lane, (lo - o) * inf for a ray parallel to a slab that
 * starts on its plane, is left out: the max gives its second operand when either is
 * NaN, so x's NaN drops x, y's drops x and y, and z's drops z, never the limits;
 * dropping a slab only meets more boxes. */
static inline int node_hit(const BvhNode *node, const SseRay *fr, Float4 limits, Float4 *lanes)
{
    const float *bounds = &node->bounds[0][0];
    Float4 x = slab_lanes(bounds, fr, 0), y = slab_lanes(bounds, fr, 1);
    Float4 z = slab_lanes(bounds, fr, 2);
    Float4 u = float4_max(float4_max(x, y), float4_max(z, limits));
    *lanes = u;
#ifdef BVH_SSE2
    __m128 sum = _mm_add_ps(u, _mm_shuffle_ps(u, u, _MM_SHUFFLE(1, 0, 3, 2)));
    return _mm_movemask_ps(_mm_cmple_ps(sum, fr->slack2)) & 3;
#else
    float s2 = fr->slack2.v[0];
    return (u.v[0] + u.v[2] <= s2) | (u.v[1] + u.v[3] <= s2) << 1;
#endif
}

/* Sets entry[k] to where the ray may enter child k, no later than it does, from the
 * lanes node_hit left: the traversal needs it only when both children are met. */
static inline void node_entries(const SseRay *fr, Float4 lanes, float entry[2])
{
#ifdef BVH_SSE2
    __m128 e = _mm_sub_ps(lanes, fr->slack);
    entry[0] = _mm_cvtss_f32(e);
    entry[1] = _mm_cvtss_f32(_mm_shuffle_ps(e, e, _MM_SHUFFLE(1, 1, 1, 1)));
#else
    entry[0] = lanes.v[0] - fr->slack.v[0];
    entry[1] = lanes.v[1] - fr->slack.v[1];
#endif
}

/* Returns the limits of the float ray fr for the interval [fr's tmin, tmax]. */
static inline Float4 float_limits(const SseRay *fr, double tmax)
{
    float t = float_above(tmax);
    return float4(fr->tmin, fr->tmin, -t, -t);
}
/* end excerpt: bvh-node-hit */

/* Tests both children's boxes of node against ray r with [tmin, tmax] as the traversal
 * does, in float: bit k set when child k's box may be met. For the tests. */
int bvh_children_hit(const Bvh *bvh, const BvhNode *node, Ray r, double tmin, double tmax)
{
    BoxRay br = box_ray(r);
    SseRay fr = float_ray(bvh, r, &br, tmin);
    Float4 lanes;
    return node_hit(node, &fr, float_limits(&fr, tmax), &lanes);
}

/* What a leaf does with a ray: tests its primitives, keeping what it needs in state,
 * and may lower *tmax, the farthest t still of interest. Returns true to stop there. */
typedef bool (*LeafFn)(const Bvh *bvh, BvhRef leaf, Ray r, double tmin, double *tmax,
                       void *state);

/* An entry of the traversal stack: a subtree still to visit and where the ray may enter it. */
typedef struct {
    uint32_t index, count; /* as in BvhRef */
    float t;
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
                                   void *state, long *box_tests)
{
    double t;
    BoxRay br = box_ray(r);
    if (bvh->prim_count == 0 || !box_hit(bvh->box, &br, tmin, *tmax, &t))
        return false;
    SseRay fr = float_ray(bvh, r, &br, tmin);
    bool negative[3] = {signbit(r.dir.x), signbit(r.dir.y), signbit(r.dir.z)};
    Float4 limits = float_limits(&fr, *tmax);
    Pending stack[BVH_MAX_DEPTH];
    int top = 0;
    uint32_t index = bvh->root.index, count = bvh->root.count; /* the subtree at hand */
    for (;;) {
        if (count > 0) {
            if (leaf(bvh, (BvhRef){index, count}, r, tmin, tmax, state))
                return true;
            limits = float_limits(&fr, *tmax);
        } else {
            /* Both children's boxes are tested; the ray goes on into the nearer one
             * and the other waits on the stack. When the ray starts inside both (the
             * entries are equal), the split axis decides: the child on the side the
             * ray comes from first. The outcomes are branches on purpose: the
             * processor guesses the next node and loads it while the test is still
             * running, where an index computed from the test's bits would wait for it. */
            const BvhNode *node = &bvh->nodes[index];
            Float4 lanes;
            int hits = node_hit(node, &fr, limits, &lanes);
            if (box_tests != NULL) /* only for --view box-tests; inlined away elsewhere */
                *box_tests += 2;
            if (hits == 3) {
                float entry[2];
                node_entries(&fr, lanes, entry);
                if (entry[0] < entry[1] || (entry[0] == entry[1] && !negative[node->axis])) {
                    stack[top++] = (Pending){node->index[1], node->count[1], entry[1]};
                    index = node->index[0];
                    count = node->count[0];
                } else {
                    stack[top++] = (Pending){node->index[0], node->count[0], entry[0]};
                    index = node->index[1];
                    count = node->count[1];
                }
                continue;
            }
            if (hits == 1) {
                index = node->index[0];
                count = node->count[0];
                continue;
            }
            if (hits == 2) {
                index = node->index[1];
                count = node->count[1];
                continue;
            }
        }
        /* Back up to the nearest waiting subtree that a hit found since has not ruled out. */
        do {
            if (top == 0)
                return false;
            top--;
        } while (stack[top].t > *tmax);
        index = stack[top].index;
        count = stack[top].count;
    }
}
/* end excerpt: bvh-traverse */

/* Finds where ray r meets primitive prim with tmin < t < tmax. */
static inline bool prim_intersect(const Scene *scene, uint32_t prim, Ray r, double tmin,
                                  double tmax, double *t)
{
    if (prim < (uint32_t)scene->sphere_count)
        return sphere_intersect(&scene->spheres[prim], r, tmin, tmax, t);
    Triangle tri = scene_triangle(scene, prim_triangle(scene, prim));
    TriangleHit th;
    if (!triangle_intersect(&tri, r, tmin, tmax, &th))
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
static bool leaf_closest(const Bvh *bvh, BvhRef leaf, Ray r, double tmin, double *tmax,
                         void *state)
{
    Closest *c = state;
    for (uint32_t k = leaf.index; k < leaf.index + leaf.count; k++) {
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
        hit->index = prim_triangle(scene, prim);
        hit->material = scene->triangles[hit->index].material;
    }
}

/* Finds the closest sphere or triangle ray r meets with tmin < t < tmax, as part 1.2's
 * world_hit would among them; sets only hit's t, kind, index and material. */
bool bvh_hit(const Bvh *bvh, Ray r, double tmin, double tmax, Hit *hit)
{
    Closest c = {.limit = tmax};
    traverse(bvh, r, tmin, &tmax, leaf_closest, &c, NULL);
    if (!c.found)
        return false;
    *hit = (Hit){.t = c.t};
    bvh_prim_surface(bvh->scene, c.which, hit);
    return true;
}

/* excerpt: bvh-leaf-any */
/* Tests a leaf's primitives for any hit at all: the first one found stops the traversal. */
static bool leaf_any(const Bvh *bvh, BvhRef leaf, Ray r, double tmin, double *tmax,
                     void *state)
{
    (void)state;
    for (uint32_t k = leaf.index; k < leaf.index + leaf.count; k++) {
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
    return traverse(bvh, r, tmin, &tmax, leaf_any, NULL, NULL);
}

/* The closest leaf box so far, and where the ray meets it. */
typedef struct {
    Closest closest;
    double t;
    Vec3 normal;
} LeafBoxes;

/* Returns the box of leaf as the build stored it: its primitives' boxes, rounded outwards. */
static Box leaf_box_of(const Bvh *bvh, BvhRef leaf)
{
    Box box = box_empty();
    for (uint32_t k = leaf.index; k < leaf.index + leaf.count; k++)
        box = box_union(box, bvh_prim_box(bvh->scene, bvh->prims[k]));
    return box_to_floats(box);
}

/* Tests a leaf's own box, as if it were a surface: mode 2 draws the leaves. */
static bool leaf_box(const Bvh *bvh, BvhRef leaf, Ray r, double tmin, double *tmax, void *state)
{
    LeafBoxes *lb = state;
    double t;
    Vec3 normal;
    if (box_hit_face(leaf_box_of(bvh, leaf), r, tmin, lb->closest.limit, &t, &normal) &&
        closest_offer(&lb->closest, leaf.index, t, tmax)) {
        lb->t = t;
        lb->normal = normal;
    }
    return false;
}

/* Finds the closest leaf box that ray r meets with tmin < t < tmax, as a surface with
 * one of the six axis normals (facing the ray) and the material of the leaf's first
 * primitive; fills in all of hit. */
bool bvh_hit_leaf_boxes(const Bvh *bvh, Ray r, double tmin, double tmax, Hit *hit)
{
    LeafBoxes lb = {.closest = {.limit = tmax}};
    traverse(bvh, r, tmin, &tmax, leaf_box, &lb, NULL);
    if (!lb.closest.found)
        return false;
    *hit = (Hit){.t = lb.t, .point = ray_at(r, lb.t), .normal = lb.normal};
    bvh_prim_surface(bvh->scene, bvh->prims[lb.closest.which], hit);
    return true;
}

/* The closest hit so far, and the primitives tested on the way: --view box-tests. */
typedef struct {
    Closest closest;
    long prim_tests;
} Counted;

/* Tests a leaf's primitives as leaf_closest does, counting them. */
static bool leaf_counted(const Bvh *bvh, BvhRef leaf, Ray r, double tmin, double *tmax,
                         void *state)
{
    Counted *c = state;
    c->prim_tests += leaf.count;
    return leaf_closest(bvh, leaf, r, tmin, tmax, &c->closest);
}

/* Returns how many boxes and primitives the search for ray r's closest hit tests. */
long bvh_count_tests(const Bvh *bvh, Ray r)
{
    Counted c = {.closest = {.limit = INFINITY}};
    double tmax = INFINITY;
    long box_tests = bvh->prim_count > 0; /* the root's */
    traverse(bvh, r, 0, &tmax, leaf_counted, &c, &box_tests);
    return box_tests + c.prim_tests;
}
