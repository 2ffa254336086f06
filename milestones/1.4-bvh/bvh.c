/* bvh.c: building a bounding volume hierarchy by the binned SAH, and tracing rays through it. */
#include "bvh.h"

#include <math.h>
#include <stdlib.h>

#include "world.h"

/* The SAH's costs: of visiting a node (two box tests), and of testing one primitive. */
#define COST_TRAVERSE 1.0
#define COST_INTERSECT 1.0

/* Returns the bin of centroid coordinate c, for bins of width 1 / scale from lo. */
static inline int bin_of(double c, double lo, double scale)
{
    int b = (int)((c - lo) * scale);
    return b < 0 ? 0 : b >= BVH_BINS ? BVH_BINS - 1 : b;
}

/* starter: todo */
/* Chooses where to split prims[begin, end) by the surface area heuristic: a ray that
 * meets a box of area A meets a child box of area A' inside it with probability about
 * A'/A, so a split into (A_L, N_L) and (A_R, N_R) costs, per ray reaching the node,
 *     C_traverse + (A_L N_L + A_R N_R) / A * C_intersect,
 * against N C_intersect for a leaf (both costs are 1). The candidates are the 15 planes
 * between the BVH_BINS bins of the centroids' box (bin_of, with scale BVH_BINS / extent)
 * on each axis it has extent on, save those that leave a side empty. Reorders
 * prims[begin, end), the left child's first, and returns the first of the right child's;
 * -1 when the box has no area or no candidate costs less than the leaf. Of equally cheap
 * candidates it keeps the first (x, then y, then z; left to right); any is correct.
 * tests/test_bvh.c: splits_by_the_sah. */
int bvh_split(Bvh *bvh, int begin, int end, Box box, Box centroids)
{
    double area = box_half_area(box);
    if (!(area > 0))
        return -1; /* a point or a line: every split looks free, the SAH cannot choose */
    int n = end - begin, best_axis = -1, best_bin = 0;
    double best_cost = n * COST_INTERSECT;
    for (int a = 0; a < 3; a++) {
        double lo = vec3_axis(centroids.lo, a), extent = vec3_axis(centroids.hi, a) - lo;
        if (!(extent > 0))
            continue; /* every centroid on one plane: nothing to split along this axis */
        /* Each bin's primitives: how many, and the box that holds them. */
        Box bin_box[BVH_BINS];
        int bin_count[BVH_BINS] = {0};
        for (int k = 0; k < BVH_BINS; k++)
            bin_box[k] = box_empty();
        for (int k = begin; k < end; k++) {
            int p = bvh->prims[k];
            int bin = bin_of(vec3_axis(bvh->centroids[p], a), lo, BVH_BINS / extent);
            bin_box[bin] = box_union(bin_box[bin], bvh->boxes[p]);
            bin_count[bin]++;
        }
        /* One sweep from the right gathers A_R N_R for each plane, one from the left A_L N_L. */
        double right_cost[BVH_BINS];
        Box right = box_empty();
        int right_n = 0;
        for (int k = BVH_BINS - 1; k > 0; k--) {
            right = box_union(right, bin_box[k]);
            right_n += bin_count[k];
            right_cost[k] = box_half_area(right) * right_n;
        }
        Box left = box_empty();
        int left_n = 0;
        for (int k = 1; k < BVH_BINS; k++) {
            left = box_union(left, bin_box[k - 1]);
            left_n += bin_count[k - 1];
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
    double lo = vec3_axis(centroids.lo, best_axis);
    double scale = BVH_BINS / (vec3_axis(centroids.hi, best_axis) - lo);
    int i = begin, j = end - 1;
    while (i <= j) {
        if (bin_of(vec3_axis(bvh->centroids[bvh->prims[i]], best_axis), lo, scale) < best_bin) {
            i++;
        } else {
            int swap = bvh->prims[i];
            bvh->prims[i] = bvh->prims[j];
            bvh->prims[j--] = swap;
        }
    }
    return i;
}

/* Stores child k of node: where it is, and its box. */
void bvh_node_set(BvhNode *node, int k, Box box, BvhRef ref)
{
    for (int a = 0; a < 3; a++) {
        node->bound[0][a][k] = vec3_axis(box.lo, a);
        node->bound[1][a][k] = vec3_axis(box.hi, a);
    }
    node->child[k] = ref;
}

/* starter: todo */
/* Builds the subtree over prims[begin, end) at depth (the root's is 0): returns where it
 * is, and its box (the union of its primitives' boxes) in *box_out. A leaf when bvh_split
 * finds no split or depth is SAH_MAX_DEPTH, unless it would hold more than BVH_MAX_LEAF:
 * then the primitives are halved as they lie. A node takes the next entry of bvh->nodes
 * before its children are built (a first child that is a node comes right after it), and
 * stores both with bvh_node_set. Counts bvh->node_count, and keeps in bvh->depth the
 * deepest depth. tests/test_bvh.c: invariants_of_random_soups and the others. */
static BvhRef build_node(Bvh *bvh, int begin, int end, int depth, Box *box_out)
{
    Box box = box_empty(), centroids = box_empty();
    for (int k = begin; k < end; k++) {
        box = box_union(box, bvh->boxes[bvh->prims[k]]);
        centroids = box_add_point(centroids, bvh->centroids[bvh->prims[k]]);
    }
    *box_out = box;
    if (depth > bvh->depth)
        bvh->depth = depth;
    int n = end - begin;
    int mid = n > 1 && depth < SAH_MAX_DEPTH ? bvh_split(bvh, begin, end, box, centroids) : -1;
    if (mid <= begin || mid >= end) {
        if (n <= BVH_MAX_LEAF)
            return (BvhRef){(uint32_t)begin, (uint32_t)n};
        mid = begin + n / 2;
    }
    uint32_t self = (uint32_t)bvh->node_count++;
    Box child_box[2];
    BvhRef left = build_node(bvh, begin, mid, depth + 1, &child_box[0]); /* node self + 1 */
    BvhRef right = build_node(bvh, mid, end, depth + 1, &child_box[1]);
    bvh_node_set(&bvh->nodes[self], 0, child_box[0], left);
    bvh_node_set(&bvh->nodes[self], 1, child_box[1], right);
    return (BvhRef){self, 0};
}

/* Builds the hierarchy of scene's spheres and triangles; false when out of memory. */
bool bvh_build(Bvh *bvh, const Scene *scene)
{
    int spheres = scene->sphere_count, planes = scene->plane_count;
    int all = spheres + planes + scene->triangle_count, n = all - planes;
    /* A binary tree of n leaves or fewer has at most n - 1 interior nodes. */
    *bvh = (Bvh){.scene = scene,
                 .nodes = malloc((size_t)(n > 1 ? n - 1 : 1) * sizeof(BvhNode)),
                 .prims = malloc((size_t)(all + 1) * sizeof(int)),
                 .prim_count = n,
                 .planes = {(uint32_t)n, (uint32_t)planes},
                 .boxes = malloc((size_t)(all + 1) * sizeof(Box)),
                 .centroids = malloc((size_t)(all + 1) * sizeof(Vec3))};
    bool ok =
        bvh->nodes != NULL && bvh->prims != NULL && bvh->boxes != NULL && bvh->centroids != NULL;
    for (int s = 0, k = 0; ok && s < all; s++) {
        bool plane = s >= spheres && s < spheres + planes;
        bvh->prims[plane ? n + s - spheres : k++] = s; /* the planes after the tree's surfaces */
        bvh->boxes[s] = box_of_surface(scene, s);
        bvh->centroids[s] = plane ? vec3(0, 0, 0) : box_center(bvh->boxes[s]);
    }
    bvh->box = box_empty();
    if (ok && n > 0)
        bvh->root = build_node(bvh, 0, n, 0, &bvh->box);
    free(bvh->boxes);
    free(bvh->centroids);
    bvh->boxes = NULL, bvh->centroids = NULL;
    if (!ok)
        bvh_free(bvh);
    return ok;
}

/* Frees what bvh_build allocated. */
void bvh_free(Bvh *bvh)
{
    free(bvh->nodes);
    free(bvh->prims);
    *bvh = (Bvh){0};
}

/* Returns the memory the hierarchy takes beyond the scene: nodes and surface numbers. */
size_t bvh_bytes(const Bvh *bvh)
{
    return (size_t)bvh->node_count * sizeof *bvh->nodes +
           (size_t)(bvh->prim_count + (int)bvh->planes.count) * sizeof *bvh->prims;
}

/* A subtree waiting on the traversal's stack, and where the ray may enter its box. */
typedef struct {
    BvhRef ref;
    double entry;
} Waiting;

/* starter: todo */
/* Returns the child of node to visit next, of those the ray meets (bit k of hits set,
 * as bvh_node_hit returns them, for child k; one at least): the only one, or of two
 * the nearer by entry (child 0 when as near), the farther then pushed onto stack at
 * *top with its entry. tests/test_bvh.c: traverse_nearer_first_and_stops. */
static inline BvhRef nearer_child(const BvhNode *node, int hits, const double entry[2],
                                  Waiting *stack, int *top)
{
    if (hits == 1)
        return node->child[0];
    if (hits == 2)
        return node->child[1];
    if (entry[1] < entry[0]) {
        stack[(*top)++] = (Waiting){node->child[0], entry[0]};
        return node->child[1];
    }
    stack[(*top)++] = (Waiting){node->child[1], entry[1]};
    return node->child[0];
}

/* starter: todo */
/* Visits every leaf whose box ray r may meet with tmin <= t <= *tmax, nearer boxes first,
 * calling leaf for each; stops, returning true, when leaf returns true. A leaf may lower
 * *tmax: boxes are then tested up to the new one. The root's box, bvh->box, is tested by
 * box_hit, a node's two children by bvh_node_hit; a subtree that waited on the stack is
 * visited only if its entry is still no farther than *tmax. Adds to *tests the boxes
 * tested (the root's, two a node) and the primitives of the leaves visited. No recursion:
 * a stack of BVH_MAX_DEPTH. tests/test_bvh.c: traverse_nearer_first_and_stops, and the
 * comparisons with brute force. */
bool bvh_traverse(const Bvh *bvh, Ray r, double tmin, double *tmax, BvhLeafFn leaf, void *state,
                  long *tests)
{
    BoxRay br = box_ray(r);
    double t_root;
    *tests += bvh->prim_count > 0;
    if (bvh->prim_count == 0 || !box_hit(bvh->box, &br, tmin, *tmax, &t_root))
        return false;
    Waiting stack[BVH_MAX_DEPTH];
    int top = 0;
    BvhRef at = bvh->root;
    for (;;) {
        if (at.count > 0) {
            *tests += at.count;
            if (leaf(bvh, at, r, tmin, tmax, state))
                return true;
        } else {
            const BvhNode *node = &bvh->nodes[at.index];
            double entry[2];
            int hits = bvh_node_hit(node, &br, tmin, *tmax, entry);
            *tests += 2;
            if (hits != 0) {
                at = nearer_child(node, hits, entry, stack, &top);
                continue;
            }
        }
        /* Back up to the nearest waiting subtree that the hits found since leave possible. */
        do {
            if (top == 0)
                return false;
            top--;
        } while (stack[top].entry > *tmax);
        at = stack[top].ref;
    }
}

/* The closest hit so far, and its surface number. */
typedef struct {
    bool found;
    int surface;
    Hit hit;
    double tmax; /* the ray's own: every primitive is tested up to it */
} Closest;

/* starter: todo */
/* Tests every primitive of a leaf (world_intersect) with tmin < t < c->tmax, the ray's own
 * tmax, not *tmax, so that a hit at exactly the best t is seen; keeps the closest hit in
 * state (a Closest) and lowers *tmax to its t, so that the traversal skips boxes beyond it.
 * The smaller (t, surface number) wins: of surfaces at the same t, world_hit keeps the
 * first it tests, and so must we. Never stops the traversal (returns false).
 * tests/test_bvh.c: leaf_closest_finds_the_closest, and every comparison with brute force. */
static bool leaf_closest(const Bvh *bvh, BvhRef leaf, Ray r, double tmin, double *tmax, void *state)
{
    Closest *c = state;
    for (uint32_t k = leaf.index; k < leaf.index + leaf.count; k++) {
        int s = bvh->prims[k];
        Hit h;
        if (world_intersect(bvh->scene, s, r, tmin, c->tmax, &h) &&
            (!c->found || h.t < c->hit.t || (h.t == c->hit.t && s < c->surface))) {
            *c = (Closest){true, s, h, c->tmax};
            *tmax = h.t;
        }
    }
    return false;
}

/* Finds the nearest surface that ray r meets with tmin < t < tmax, exactly as part 1.2's
 * world_hit: the tree's spheres and triangles, then the planes; fills in hit. Adds to
 * *tests the boxes and primitives of the tree tested (bvh_traverse), for --view box-tests. */
bool bvh_hit(const Bvh *bvh, Ray r, double tmin, double tmax, Hit *hit, long *tests)
{
    Closest c = {.tmax = tmax};
    bvh_traverse(bvh, r, tmin, &tmax, leaf_closest, &c, tests);
    leaf_closest(bvh, bvh->planes, r, tmin, &tmax, &c);
    if (!c.found)
        return false;
    *hit = c.hit;
    world_complete_hit(bvh->scene, r, hit);
    return true;
}

/* starter: todo */
/* Tests a leaf's primitives for any hit with tmin < t < *tmax (world_intersect): returns
 * true at the first one, which stops the traversal; leaves *tmax as it is.
 * tests/test_bvh.c: leaf_any_within_tmin_and_tmax. */
static bool leaf_any(const Bvh *bvh, BvhRef leaf, Ray r, double tmin, double *tmax, void *state)
{
    (void)state;
    Hit h;
    for (uint32_t k = leaf.index; k < leaf.index + leaf.count; k++)
        if (world_intersect(bvh->scene, bvh->prims[k], r, tmin, *tmax, &h))
            return true;
    return false;
}

/* Tells whether any surface lies on ray r with tmin < t < tmax. */
bool bvh_blocked(const Bvh *bvh, Ray r, double tmin, double tmax)
{
    long tests = 0;
    return bvh_traverse(bvh, r, tmin, &tmax, leaf_any, NULL, &tests) ||
           leaf_any(bvh, bvh->planes, r, tmin, &tmax, NULL);
}
