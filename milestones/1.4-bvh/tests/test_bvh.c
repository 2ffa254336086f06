/* test_bvh.c: the BVH's invariants, and its answers equal to brute force for random rays. */
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "accel.h"
#include "bvh.h"
#include "camera.h"
#include "testing.h"
#include "world.h"

/* Returns the time in seconds on a clock that only goes forward. */
static double seconds_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* When the last progress line was printed, or 0 before the first call in this test's
 * process: the long steps print one every 2 s or so, so that a student does not take a
 * long test for a hung one. */
static double progress_last;

/* Prints "test_bvh: " and what the long step now starting does, on the standard error,
 * which shows it at once. */
static void progress(const char *format, ...)
{
    va_list args;
    va_start(args, format);
    fputs("test_bvh: ", stderr);
    vfprintf(stderr, format, args);
    fputs("...\n", stderr);
    va_end(args);
    progress_last = seconds_now();
}

/* Prints how far a long loop is, done of total things, if 2 s have passed since the last
 * line (or since the first call, in a test that has printed none). */
static void progress_tick(long done, long total, const char *things)
{
    if (progress_last == 0)
        progress_last = seconds_now();
    if (seconds_now() - progress_last < 2)
        return;
    fprintf(stderr, "test_bvh:   %ld of %ld %s\n", done, total, things);
    progress_last = seconds_now();
}

/* A small deterministic random generator (xorshift64*), so that failures repeat. */
static uint64_t rng_state = 0x9E3779B97F4A7C15u;

/* Returns a uniform random number in [0, 1). */
static double rnd(void)
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return (double)((rng_state * 0x2545F4914F6CDD1Du) >> 11) * 0x1p-53;
}

/* Returns a random point in the cube [lo, hi]^3. */
static Vec3 rnd_point(double lo, double hi)
{
    return vec3(lo + (hi - lo) * rnd(), lo + (hi - lo) * rnd(), lo + (hi - lo) * rnd());
}

/* Returns a random unit direction; one in five has one or two zero components, of
 * either sign, so that the slab test sees infinite inverse directions. */
static Vec3 rnd_dir(void)
{
    Vec3 d;
    do
        d = rnd_point(-1, 1);
    while (vec3_length_squared(d) > 1 || vec3_length_squared(d) < 1e-6);
    if (rnd() < 0.2) {
        double zero = rnd() < 0.5 ? 0.0 : -0.0;
        if (rnd() < 0.5)
            d.x = zero;
        else
            d.y = zero;
        if (rnd() < 0.3)
            d.z = zero;
        if (d.x == 0 && d.y == 0 && d.z == 0)
            d.z = 1;
    }
    return vec3_normalize(d);
}

/* Sets triangle k of scene to a, b, c in material: its corners are vertices 3k to
 * 3k + 2, its own. */
static void set_triangle(Scene *scene, int k, Vec3 a, Vec3 b, Vec3 c, int material)
{
    scene->vertices[3 * k] = a;
    scene->vertices[3 * k + 1] = b;
    scene->vertices[3 * k + 2] = c;
    scene->triangles[k] = (Face){{3 * k, 3 * k + 1, 3 * k + 2}, material, 0};
}

/* Fills scene with n random triangles of size about size in the unit cube, spheres
 * spheres and planes planes. Some triangles repeat an earlier one exactly (ties of t),
 * some have no area. */
static void random_scene(Scene *scene, int n, double size, int spheres, int planes)
{
    *scene = (Scene){0};
    scene->vertices = malloc((size_t)(n > 0 ? 3 * n : 1) * sizeof *scene->vertices);
    scene->vertex_count = 3 * n;
    scene->triangles = malloc((size_t)(n > 0 ? n : 1) * sizeof *scene->triangles);
    scene->spheres = malloc((size_t)(spheres > 0 ? spheres : 1) * sizeof *scene->spheres);
    scene->planes = malloc((size_t)(planes > 0 ? planes : 1) * sizeof *scene->planes);
    for (int k = 0; k < n; k++) {
        Vec3 a = rnd_point(0, 1), b = vec3_add(a, vec3_scale(rnd_point(-1, 1), size)),
             c = vec3_add(a, vec3_scale(rnd_point(-1, 1), size));
        double u = rnd();
        if (k > 0 && u < 0.05) { /* the same triangle again */
            Triangle t = scene_triangle(scene, (int)(rnd() * k));
            a = *t.a, b = *t.b, c = *t.c;
        } else if (u < 0.08) {
            c = vec3_add(a, vec3_scale(vec3_sub(b, a), 2)); /* no area */
        }
        set_triangle(scene, k, a, b, c, k % 3);
    }
    for (int k = 0; k < spheres; k++)
        scene->spheres[k] = (Sphere){rnd_point(0, 1), 0.01 + 0.1 * rnd(), k % 2, 0};
    for (int k = 0; k < planes; k++)
        scene->planes[k] = (Plane){rnd_dir(), -0.5 + rnd(), 2, 0};
    scene->triangle_count = n;
    scene->sphere_count = spheres;
    scene->plane_count = planes;
    scene->materials = calloc(3, sizeof *scene->materials);
    scene->material_count = 3;
}

/* Writes into buf the name of surface s of scene (a number of world_intersect). */
static const char *surface_name(const Scene *scene, int s, char *buf, size_t size)
{
    int planes = scene->sphere_count + scene->plane_count;
    if (s >= 0 && s < scene->sphere_count)
        snprintf(buf, size, "sphere %d", s);
    else if (s >= scene->sphere_count && s < planes)
        snprintf(buf, size, "plane %d", s - scene->sphere_count);
    else if (s >= planes && s < planes + scene->triangle_count)
        snprintf(buf, size, "triangle %d", s - planes);
    else
        snprintf(buf, size, "surface number %d, which the scene does not have", s);
    return buf;
}

/* Returns the ending of a count of n things: "" for one, "s" for more or none. */
static const char *plural(int n)
{
    return n == 1 ? "" : "s";
}

/* Tells whether box inner lies inside box outer (faces may touch). */
static bool box_contains(Box outer, Box inner)
{
    return outer.lo.x <= inner.lo.x && outer.lo.y <= inner.lo.y && outer.lo.z <= inner.lo.z &&
           inner.hi.x <= outer.hi.x && inner.hi.y <= outer.hi.y && inner.hi.z <= outer.hi.z;
}

/* Writes box b into buf as [(lo) to (hi)], with digits enough to show box_pad's margin. */
static const char *box_text(Box b, char *buf, size_t size)
{
    snprintf(buf, size, "[(%.9g, %.9g, %.9g) to (%.9g, %.9g, %.9g)]", b.lo.x, b.lo.y, b.lo.z,
             b.hi.x, b.hi.y, b.hi.z);
    return buf;
}

/* Returns the box of sphere or triangle s of scene as box.c's contract has it, worked out
 * here rather than asked of box_of_surface, so that a leaf is held to the box its
 * primitive should have: the least and greatest coordinates, grown by box_pad if padded. */
static Box reference_box(const Scene *scene, int s, bool padded)
{
    Box b;
    if (s < scene->sphere_count) {
        const Sphere *sphere = &scene->spheres[s];
        Vec3 r = vec3(sphere->radius, sphere->radius, sphere->radius);
        b = (Box){vec3_sub(sphere->center, r), vec3_add(sphere->center, r)};
    } else {
        Triangle t = scene_triangle(scene, s - scene->sphere_count - scene->plane_count);
        b = box_add_point(box_add_point((Box){*t.a, *t.a}, *t.b), *t.c);
    }
    return padded ? box_pad(b) : b;
}

/* What walking a hierarchy found, and the first thing wrong with it, in words. */
typedef struct {
    const Bvh *bvh;
    int *leaf_of;  /* for each surface: the leaf it is in, or -1 */
    int *named_by; /* for each node: the reference to it (see ref_name), or -2 before */
    int nodes, leaves, depth, found; /* found: the primitives of the leaves walked */
    char wrong[900];
} Walk;

/* Writes into buf the name of reference who: -1 the root (bvh->root), 2 p + k child k of
 * node p; and into box_buf, if not NULL, the name of the box it has there. */
static const char *ref_name(int who, char *buf, size_t size, char *box_buf, size_t box_size)
{
    if (who < 0)
        snprintf(buf, size, "the root");
    else
        snprintf(buf, size, "node %d's child %d", who / 2, who % 2);
    if (box_buf != NULL && who < 0)
        snprintf(box_buf, box_size, "the root's box (bvh->box)");
    else if (box_buf != NULL)
        snprintf(box_buf, box_size, "node %d's box of its child %d", who / 2, who % 2);
    return buf;
}

/* Returns the box of child k of node. */
static Box node_box(const BvhNode *node, int k)
{
    return (Box){vec3(node->bound[0][0][k], node->bound[0][1][k], node->bound[0][2][k]),
                 vec3(node->bound[1][0][k], node->bound[1][1][k], node->bound[1][2][k])};
}

/* Checks the leaf ref, named by who, whose box is box: its run of prims, each primitive
 * once in the whole tree and inside the box, padded; false, with w->wrong said, if not. */
static bool walk_leaf(Walk *w, BvhRef ref, Box box, int who)
{
    const Bvh *bvh = w->bvh;
    const Scene *scene = bvh->scene;
    char self[60], whose[80], name[100], inner[160], outer[160];
    ref_name(who, self, sizeof self, whose, sizeof whose);
    int leaf = w->leaves++;
    progress_tick(w->found, bvh->prim_count, "primitives found in their leaves");
    if (ref.count > BVH_MAX_LEAF || ref.index + (uint64_t)ref.count > (uint64_t)bvh->prim_count) {
        snprintf(w->wrong, sizeof w->wrong,
                 "leaf %d (%s) holds prims[%u] to prims[%u], but a leaf "
                 "holds at most BVH_MAX_LEAF (%d) of the %d entries",
                 leaf, self, ref.index, ref.index + ref.count - 1, BVH_MAX_LEAF, bvh->prim_count);
        return false;
    }
    for (uint32_t k = ref.index; k < ref.index + ref.count; k++) {
        int p = bvh->prims[k];
        bool plane = p >= scene->sphere_count && p < scene->sphere_count + scene->plane_count;
        surface_name(scene, p, name, sizeof name);
        if (plane || p < 0 ||
            p >= scene->sphere_count + scene->plane_count + scene->triangle_count) {
            snprintf(w->wrong, sizeof w->wrong,
                     "leaf %d (%s) holds %s: a leaf holds spheres and triangles only", leaf, self,
                     name);
            return false;
        }
        if (w->leaf_of[p] >= 0) {
            if (w->leaf_of[p] == leaf)
                snprintf(w->wrong, sizeof w->wrong, "leaf %d (%s) holds %s twice", leaf, self,
                         name);
            else
                snprintf(
                    w->wrong, sizeof w->wrong,
                    "%s is in leaf %d and in leaf %d (%s): every primitive belongs in one leaf",
                    name, w->leaf_of[p], leaf, self);
            return false;
        }
        w->leaf_of[p] = leaf;
        w->found++;
        Box padded = reference_box(scene, p, true);
        if (box_contains(box, padded))
            continue;
        if (box_contains(box, reference_box(scene, p, false)))
            snprintf(w->wrong, sizeof w->wrong,
                     "leaf %d (%s) holds %s, whose box, grown by box_pad's margin (2^-20 of its "
                     "largest coordinate, on every side), is %s; the leaf's box, %s, %s, holds "
                     "the %s but not the margin: box_of_sphere and box_of_triangle must grow "
                     "every surface's box by box_pad, or a ray through a corner may miss the box "
                     "yet hit the surface",
                     leaf, self, name, box_text(padded, inner, sizeof inner), whose,
                     box_text(box, outer, sizeof outer),
                     p < scene->sphere_count ? "sphere" : "triangle");
        else
            snprintf(w->wrong, sizeof w->wrong,
                     "%s, %s, does not hold %s, whose box is %s, though the leaf (leaf %d) holds "
                     "it: a leaf's box must hold its primitives' boxes; build_node returns in "
                     "*box_out the union of its primitives' boxes (bvh->boxes), not of their "
                     "centroids",
                     whose, box_text(box, outer, sizeof outer), name,
                     box_text(padded, inner, sizeof inner), leaf);
        return false;
    }
    return true;
}

static bool walk(Walk *w, BvhRef ref, Box box, int who, int depth);

/* Checks the interior node that ref, named by who, names, and its subtree (box is the box
 * it has there): a node that exists, named once, whose box holds its children's boxes;
 * false, with w->wrong said, at the first thing wrong. */
static bool walk_node(Walk *w, BvhRef ref, Box box, int who, int depth)
{
    const Bvh *bvh = w->bvh;
    char self[60], whose[80], other[60], inner[160], outer[160];
    ref_name(who, self, sizeof self, whose, sizeof whose);
    /* A reference of count 0 names a node, so a leaf of 0 primitives poses as one. */
    const char *empty_leaf = "is it a leaf of 0 primitives, whose count of 0 makes it a node's "
                             "reference? build_node must never build a subtree over no "
                             "primitives (a split that leaves one side empty)";
    if (who < 0 && bvh->node_count == 0) {
        snprintf(w->wrong, sizeof w->wrong,
                 "the root has a count of 0, so it names node %u, but build_node made no node "
                 "(bvh->node_count is 0): is build_node written yet? A leaf's count is 1 to "
                 "BVH_MAX_LEAF, never 0",
                 ref.index);
        return false;
    }
    if (ref.index >= (uint32_t)bvh->node_count) {
        snprintf(w->wrong, sizeof w->wrong,
                 "%s has a count of 0, so it names node %u, but build_node made only nodes 0 to "
                 "%d: %s",
                 self, ref.index, bvh->node_count - 1, empty_leaf);
        return false;
    }
    if (w->named_by[ref.index] != -2) {
        snprintf(w->wrong, sizeof w->wrong,
                 "%s and %s both name node %u, but a node has one parent: %s; or else a node "
                 "names itself or a node above it",
                 ref_name(w->named_by[ref.index], other, sizeof other, NULL, 0), self, ref.index,
                 empty_leaf);
        return false;
    }
    w->named_by[ref.index] = who;
    w->nodes++;
    const BvhNode *node = &bvh->nodes[ref.index];
    for (int c = 0; c < 2; c++) {
        Box child = node_box(node, c);
        if (!box_contains(box, child)) {
            snprintf(w->wrong, sizeof w->wrong,
                     "node %u's box of its child %d, %s, does not lie inside %s, %s, the box of "
                     "node %u itself: a node's box must hold its children's boxes; build_node "
                     "returns in *box_out the union of all its primitives' boxes",
                     ref.index, c, box_text(child, inner, sizeof inner), whose,
                     box_text(box, outer, sizeof outer), ref.index);
            return false;
        }
        if (!walk(w, node->child[c], child, 2 * (int)ref.index + c, depth + 1))
            return false;
    }
    return true;
}

/* Checks the subtree at ref, named by who, whose box is box, at depth (the root's 0):
 * no deeper than BVH_MAX_DEPTH, then as a leaf or a node; false, with w->wrong said, at
 * the first thing wrong. */
static bool walk(Walk *w, BvhRef ref, Box box, int who, int depth)
{
    char self[60];
    if (depth > w->depth)
        w->depth = depth;
    if (depth > BVH_MAX_DEPTH) {
        snprintf(w->wrong, sizeof w->wrong,
                 "%s lies %d levels below the root: the tree is deeper than BVH_MAX_DEPTH (%d), "
                 "the cap bvh_traverse's stack of BVH_MAX_DEPTH subtrees relies on; below some "
                 "depth (bvh.h: SAH_MAX_DEPTH, each child one level below its node) build_node "
                 "must stop asking bvh_split and halve its primitives as they lie",
                 ref_name(who, self, sizeof self, NULL, 0), depth, BVH_MAX_DEPTH);
        return false;
    }
    return ref.count > 0 ? walk_leaf(w, ref, box, who) : walk_node(w, ref, box, who, depth);
}

/* Builds the BVH of scene, which what names, and checks every invariant of its structure:
 * no more nodes than a tree over its primitives can have, no empty leaf, no node named
 * twice, no deeper than BVH_MAX_DEPTH, every sphere and triangle in exactly one leaf,
 * inside every box above it; and what the build counted is what is there. */
static void check_invariants(const Scene *scene, const char *what)
{
    Bvh bvh;
    ck_assert_msg(bvh_build(&bvh, scene), "bvh_build failed");
    int n = scene->sphere_count + scene->triangle_count;
    progress_tick(0, n, "primitives found in their leaves"); /* the build done, if it was long */
    int all = n + scene->plane_count;
    char counts[80];
    snprintf(counts, sizeof counts, "%d sphere%s, %d triangle%s", scene->sphere_count,
             plural(scene->sphere_count), scene->triangle_count, plural(scene->triangle_count));
    ck_assert_int_eq(bvh.prim_count, n);
    if (n == 0) {
        ck_assert_msg(bvh.node_count == 0,
                      "the BVH of %s, which has no sphere or triangle, has %d nodes, not 0", what,
                      bvh.node_count);
        bvh_free(&bvh);
        return;
    }
    /* Checked first: more nodes than that have been written past the end of bvh->nodes. */
    ck_assert_msg(bvh.node_count <= n - 1,
                  "the BVH of %s (%s): build_node made %d interior node%s for n = %d: with their "
                  "leaves, more than the 2n - 1 = %d nodes a tree over n primitives can have (n "
                  "leaves at most, and one interior node fewer), and more than bvh_build's array "
                  "of n - 1 nodes holds: does build_node take a node's entry before it knows it "
                  "will split (a leaf takes none), or make leaves of 0 primitives?",
                  what, counts, bvh.node_count, plural(bvh.node_count), n, 2 * n - 1);
    Walk w = {.bvh = &bvh,
              .leaf_of = malloc((size_t)all * sizeof(int)),
              .named_by = malloc((size_t)(bvh.node_count > 0 ? bvh.node_count : 1) * sizeof(int))};
    for (int p = 0; p < all; p++)
        w.leaf_of[p] = -1;
    for (int k = 0; k < bvh.node_count; k++)
        w.named_by[k] = -2;
    bool ok = walk(&w, bvh.root, bvh.box, -1, 0);
    char name[100];
    for (int p = 0; ok && p < all; p++)
        if (w.leaf_of[p] < 0 &&
            (p < scene->sphere_count || p >= scene->sphere_count + scene->plane_count)) {
            snprintf(w.wrong, sizeof w.wrong, "%s is in no leaf",
                     surface_name(scene, p, name, sizeof name));
            ok = false;
        }
    free(w.leaf_of);
    free(w.named_by);
    ck_assert_msg(ok, "the BVH of %s (%s): %s", what, counts, w.wrong);
    /* What the build counted is what is there; a binary tree of L leaves has L - 1 nodes. */
    ck_assert_msg(w.nodes == bvh.node_count,
                  "the BVH of %s: build_node took %d entries of bvh->nodes, but %d nodes are in "
                  "the tree: %s",
                  what, bvh.node_count, w.nodes,
                  bvh.node_count > w.nodes
                      ? "a leaf takes no entry; a node takes one once it knows it will split"
                      : "bvh->node_count must count every node made");
    ck_assert_msg(w.depth == bvh.depth,
                  "the BVH of %s: build_node keeps %d as the deepest depth (bvh->depth), but the "
                  "tree goes %d levels below the root",
                  what, bvh.depth, w.depth);
    ck_assert_msg(w.nodes == w.leaves - 1,
                  "the BVH of %s: %d leaves, but %d interior nodes, not %d", what, w.leaves,
                  w.nodes, w.leaves - 1);
    bvh_free(&bvh);
}

START_TEST(invariants_of_random_soups)
{
    int sizes[] = {0, 1, 2, 3, 17, 1000, 20000};
    for (size_t k = 0; k < sizeof sizes / sizeof sizes[0]; k++) {
        Scene scene;
        random_scene(&scene, sizes[k], 0.05, sizes[k] / 10, 0);
        check_invariants(&scene, "a random soup");
        scene_free(&scene);
    }
}
END_TEST

START_TEST(invariants_of_degenerate_sets)
{
    Scene scene;
    /* 500 copies of one triangle: every centroid equal, nothing for the SAH to split. */
    random_scene(&scene, 500, 0.05, 0, 0);
    for (int k = 1; k < 500; k++)
        scene.triangles[k] = scene.triangles[0];
    check_invariants(&scene, "500 copies of one triangle");
    /* Triangles without area, all on one line. */
    for (int k = 0; k < 500; k++)
        set_triangle(&scene, k, vec3(k, 0, 0), vec3(k + 1, 0, 0), vec3(k + 2, 0, 0), 0);
    check_invariants(&scene, "500 triangles without area on one line");
    /* Points: triangles whose three corners coincide, some at the same place. */
    for (int k = 0; k < 500; k++) {
        Vec3 p = vec3(k % 7, 0, 0);
        set_triangle(&scene, k, p, p, p, 0);
    }
    check_invariants(&scene, "500 triangles shrunk to points at 7 places");
    /* Depth: sizes doubling, each triangle twice as far as the last, a chain for the SAH. */
    for (int k = 0; k < 500; k++) {
        double x = ldexp(1, k % 60);
        set_triangle(&scene, k, vec3(x, 0, 0), vec3(x, 1, 0), vec3(x, 0, 1), 0);
    }
    check_invariants(&scene, "500 triangles at x = 2^(k mod 60)");
    scene_free(&scene);
    /* Planes only: no primitive in the hierarchy at all. */
    random_scene(&scene, 0, 0.05, 0, 3);
    check_invariants(&scene, "3 planes alone");
    scene_free(&scene);
}
END_TEST

START_TEST(tests_counted_for_the_box_tests_view)
{
    /* One triangle: its leaf is the root. A ray that meets the root's box tests it and
     * the triangle (2); one that misses it tests the root's box only (1). */
    Scene scene;
    random_scene(&scene, 1, 0.05, 0, 0);
    set_triangle(&scene, 0, vec3(-1, -1, -5), vec3(1, -1, -5), vec3(0, 1, -5), 0);
    Accel accel;
    ck_assert(accel_build(&accel, &scene, ACCEL_BVH));
    Surfaces s = accel_surfaces(&accel);
    ck_assert_int_eq(s.tests(s.data, ray(vec3(0, 0, 0), vec3(0, 0, -1))), 2);
    ck_assert_int_eq(s.tests(s.data, ray(vec3(0, 0, 0), vec3(0, 0, 1))), 1);
    accel_free(&accel);
    scene_free(&scene);
}
END_TEST

/* Box k of the SAH's test: unit boxes, six in a cluster at x = 0, one at x = 4 and one at x = 10. */
static Box sah_box(int k)
{
    double x = k < 6 ? 0.01 * k : k == 6 ? 4 : 10;
    return (Box){vec3(x, 0, 0), vec3(x + 1, 1, 1)};
}

START_TEST(splits_by_the_sah)
{
    /* Split after the cluster: 1 + (3 * 6 + A(x in [4, 11]) 15 * 2) / 23.06 = 3.08; after
     * the box at 4: 1 + (11.06 * 7 + 3 * 1) / 23.06 = 4.49. Without the counts the second
     * would look cheaper. The primitives come shuffled. */
    Box boxes[8];
    Vec3 centroids[8];
    int prims[8] = {7, 2, 6, 0, 5, 3, 1, 4};
    Box box = box_empty(), centroid_box = box_empty();
    for (int k = 0; k < 8; k++) {
        boxes[k] = sah_box(k);
        centroids[k] = box_center(boxes[k]);
        box = box_union(box, boxes[k]);
        centroid_box = box_add_point(centroid_box, centroids[k]);
    }
    Bvh b = {.boxes = boxes, .centroids = centroids, .prims = prims};
    int mid = bvh_split(&b, 0, 8, box, centroid_box);
    ck_assert_msg(mid == 6,
                  "bvh_split of eight unit boxes, six at x = 0, one at x = 4 and one at x = 10, "
                  "returns %d, not 6: the split after the six costs 3.08, after the box at 4 "
                  "4.49 (C_traverse + (A_L N_L + A_R N_R) / A)",
                  mid);
    int seen = 0;
    for (int k = 0; k < 8; k++) {
        ck_assert_msg(prims[k] >= 0 && prims[k] < 8 && !(seen >> prims[k] & 1),
                      "bvh_split: prims[%d] is %d; the primitives must be reordered, each kept once",
                      k, prims[k]);
        seen |= 1 << prims[k];
        ck_assert_msg((k < 6) == (prims[k] < 6),
                      "bvh_split: prims[%d] is box %d, on the wrong side of the split at %d", k,
                      prims[k], mid);
    }
    /* Two boxes almost one in the other: a split costs 1 + (3 + 3) / 3.06 = 2.96, a leaf
     * of two 2, so no split; and none where the box has no area. */
    boxes[1] = (Box){vec3(0.01, 0.01, 0.01), vec3(1.01, 1.01, 1.01)};
    centroids[1] = box_center(boxes[1]);
    int two[2] = {0, 1};
    b.prims = two;
    mid = bvh_split(&b, 0, 2, box_union(boxes[0], boxes[1]),
                    (Box){centroids[0], centroids[1]});
    ck_assert_msg(mid == -1,
                  "bvh_split of two unit boxes, one 0.01 from the other, returns %d, not -1: a "
                  "split costs 1 + (3 + 3) / 3.06 = 2.96, the leaf 2",
                  mid);
    Box flat = {vec3(0, 0, 0), vec3(1, 0, 0)};
    mid = bvh_split(&b, 0, 2, flat, flat);
    ck_assert_msg(mid == -1, "bvh_split of a box without area returns %d, not -1", mid);
}
END_TEST

/* Two triangles across the z axis, at z = -5 (triangle 0) and z = -10 (triangle 1): two
 * leaves under one node. */
static void two_leaves(Scene *scene)
{
    random_scene(scene, 2, 0.05, 0, 0);
    set_triangle(scene, 0, vec3(-1, -1, -5), vec3(3, -1, -5), vec3(-1, 3, -5), 0);
    set_triangle(scene, 1, vec3(-1, -1, -10), vec3(3, -1, -10), vec3(-1, 3, -10), 1);
}

/* A leaf function that counts its calls in state and stops, or lowers *tmax to 1, as the
 * test asks in how. */
typedef struct {
    int calls;
    int how; /* 0: go on; 1: stop; 2: lower *tmax to 1 */
} LeafCalls;

/* Counts a leaf's visit, and does what calls->how says. */
static bool count_leaf(const Bvh *bvh, BvhRef leaf, Ray r, double tmin, double *tmax, void *state)
{
    (void)bvh, (void)leaf, (void)r, (void)tmin;
    LeafCalls *calls = state;
    calls->calls++;
    if (calls->how == 2)
        *tmax = 1;
    return calls->how == 1;
}

START_TEST(traverse_nearer_first_and_stops)
{
    Scene scene;
    two_leaves(&scene);
    Bvh bvh;
    ck_assert(bvh_build(&bvh, &scene));
    ck_assert_msg(bvh.node_count == 1 && bvh.root.count == 0 && bvh.nodes[0].child[0].count == 1 &&
                      bvh.nodes[0].child[1].count == 1,
                  "build_node: two triangles 5 apart make %d nodes, not 1 node of two leaves",
                  bvh.node_count);
    /* From either side, the nearer leaf's hit rules the farther leaf out: the root's box,
     * the node's two and one triangle, 4 tests. Farther first, or not reading *tmax
     * again, makes 5. */
    Vec3 from[2] = {vec3(0, 0, 0), vec3(0, 0, -20)}, along[2] = {vec3(0, 0, -1), vec3(0, 0, 1)};
    for (int k = 0; k < 2; k++) {
        long tests = 0;
        Hit hit;
        bvh_hit(&bvh, ray(from[k], along[k]), 0, INFINITY, &hit, &tests);
        ck_assert_msg(tests == 4,
                      "bvh_traverse (nearer_child, leaf_closest) along %sz: %ld boxes and triangles "
                      "tested, not 4: the nearer child first, and a subtree beyond the closest hit "
                      "(*tmax, which leaf_closest lowers) not visited",
                      k == 0 ? "-" : "+", tests);
    }
    long tests = 0;
    double tmax = INFINITY;
    LeafCalls calls = {0, 1};
    bool stopped = bvh_traverse(&bvh, ray(from[0], along[0]), 0, &tmax, count_leaf, &calls, &tests);
    ck_assert_msg(stopped && calls.calls == 1,
                  "bvh_traverse: a leaf function that returns true is called %d times, and the "
                  "traversal returns %s: it must stop there, returning true",
                  calls.calls, stopped ? "true" : "false");
    calls = (LeafCalls){0, 0};
    stopped = bvh_traverse(&bvh, ray(from[0], along[0]), 0, &tmax, count_leaf, &calls, &tests);
    ck_assert_msg(!stopped && calls.calls == 2,
                  "bvh_traverse: a ray through both leaves, whose function goes on, visits %d "
                  "leaves, not 2, and returns %s, not false",
                  calls.calls, stopped ? "true" : "false");
    calls = (LeafCalls){0, 2};
    bvh_traverse(&bvh, ray(from[0], along[0]), 0, &tmax, count_leaf, &calls, &tests);
    ck_assert_msg(calls.calls == 1,
                  "bvh_traverse: after a leaf lowers *tmax to 1, the other leaf, at t = 10, is "
                  "visited: the boxes are tested up to *tmax as it is now");
    bvh_free(&bvh);
    scene_free(&scene);
}
END_TEST

/* Builds in bvh, over scene, one leaf of two triangles one over the other across the z
 * axis: triangle 0 slanted from z = -6 to -9, met at z = -6.75, triangle 1 at z = -5. */
static void one_leaf(Scene *scene, Bvh *bvh)
{
    two_leaves(scene);
    set_triangle(scene, 0, vec3(-1, -1, -6), vec3(3, -1, -6), vec3(-1, 3, -9), 0);
    set_triangle(scene, 1, vec3(-1, -1, -5), vec3(3, -1, -5), vec3(-1, 3, -5), 1);
    ck_assert(bvh_build(bvh, scene));
    ck_assert_msg(bvh->root.count == 2,
                  "build_node (bvh_split): two triangles one over the other make no leaf of two "
                  "(a split costs 1 + (40 + 16) / 48 = 2.17, the leaf 2)");
}

START_TEST(leaf_closest_finds_the_closest)
{
    /* One leaf of two triangles, the farther first. */
    Scene scene;
    Bvh bvh;
    one_leaf(&scene, &bvh);
    Hit hit;
    long tests = 0;
    bool found = bvh_hit(&bvh, ray(vec3(0, 0, 0), vec3(0, 0, -1)), 0, INFINITY, &hit, &tests);
    ck_assert_msg(found && hit.index == 1 && hit.t == 5,
                  "leaf_closest: in a leaf of two triangles at t = 6.75 and t = 5, bvh_hit finds "
                  "%s%d at t = %g, not triangle 1 at t = 5: the closest of the leaf, not the first",
                  found ? "triangle " : "nothing, ", found ? hit.index : 0, found ? hit.t : 0);
    bvh_free(&bvh);
    scene_free(&scene);
}
END_TEST

START_TEST(leaf_any_within_tmin_and_tmax)
{
    /* One leaf, its box from t = 5 to 9: each range reaches the box, so that leaf_any
     * alone decides. */
    Scene scene;
    Bvh bvh;
    one_leaf(&scene, &bvh);
    Ray r = ray(vec3(0, 0, 0), vec3(0, 0, -1)); /* triangles at t = 6.75 and t = 5 */
    double range[4][2] = {{0, 5}, {7, INFINITY}, {0, 5.5}, {5.5, INFINITY}};
    for (int k = 0; k < 4; k++) {
        bool want = k >= 2, got = bvh_blocked(&bvh, r, range[k][0], range[k][1]);
        ck_assert_msg(got == want,
                      "leaf_any: with triangles at t = 5 and t = 6.75, bvh_blocked from tmin = %g "
                      "to tmax = %g says %s: only a hit with tmin < t < tmax blocks",
                      range[k][0], range[k][1], got ? "blocked" : "not blocked");
    }
    bvh_free(&bvh);
    scene_free(&scene);
}
END_TEST

/* Tells whether a and b are the same vector, bit for bit but for the sign of zero. */
static bool vec3_equal(Vec3 a, Vec3 b)
{
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

/* Writes into buf what a search found: a surface and its t, or nothing. */
static const char *found_name(const Scene *scene, bool found, const Hit *hit, char *buf,
                              size_t size)
{
    if (!found)
        return "nothing";
    char name[100];
    snprintf(buf, size, "%s at t = %.17g",
             surface_name(scene, world_surface_id(scene, hit), name, sizeof name), hit->t);
    return buf;
}

/* Tells, in why, how the BVH's answers for ray r with [tmin, tmax] differ from brute
 * force's: the closest hit (and every field of its record), and whether it is blocked.
 * Sets *found to whether brute force finds a hit, and then *want to it. */
static bool same_as_brute_force(const Bvh *bvh, Ray r, double tmin, double tmax, bool *found,
                                Hit *want_out, char *why, size_t size)
{
    const Scene *scene = bvh->scene;
    Hit want, got;
    char a[160], b[160];
    long tests = 0;
    bool wanted = world_hit(scene, r, tmin, tmax, &want);
    bool have = bvh_hit(bvh, r, tmin, tmax, &got, &tests);
    *found = wanted;
    if (wanted)
        *want_out = want;
    if (have != wanted ||
        (wanted && (got.t != want.t || got.kind != want.kind || got.index != want.index ||
                    got.material != want.material || got.back_face != want.back_face ||
                    !vec3_equal(got.point, want.point) || !vec3_equal(got.normal, want.normal)))) {
        snprintf(why, size, "bvh_hit (bvh_traverse, leaf_closest) finds %s, brute force finds %s",
                 found_name(scene, have, &got, a, sizeof a),
                 found_name(scene, wanted, &want, b, sizeof b));
        return false;
    }
    if (bvh_blocked(bvh, r, tmin, tmax) != wanted) {
        snprintf(why, size, "bvh_blocked (bvh_traverse, leaf_any) says %s, but brute force finds %s",
                 wanted ? "nothing blocks it" : "something blocks it",
                 found_name(scene, wanted, &want, b, sizeof b));
        return false;
    }
    return true;
}

/* Compares the BVH's closest hit and blocked() with brute force for count random rays
 * from points in [lo, hi]^3 on scene, half of them aimed at a point of the scene's box,
 * half in any direction; tmax is random for half of them. */
static void compare_with_brute_force(const Scene *scene, int count, double lo, double hi)
{
    progress("comparing %d random rays with brute force over %d spheres and %d triangles", count,
             scene->sphere_count, scene->triangle_count);
    Bvh bvh;
    ck_assert(bvh_build(&bvh, scene));
    Box all = bvh.box;
    int hits = 0;
    for (int k = 0; k < count; k++) {
        progress_tick(k, count, "rays");
        Vec3 o = rnd_point(lo, hi), target = vec3_add(all.lo, vec3(rnd() * (all.hi.x - all.lo.x),
                                                                   rnd() * (all.hi.y - all.lo.y),
                                                                   rnd() * (all.hi.z - all.lo.z)));
        Vec3 to = vec3_sub(target, o);
        Ray r = ray(o, rnd() < 0.5 && vec3_length(to) > 0 ? vec3_normalize(to) : rnd_dir());
        double tmax = rnd() < 0.5 ? INFINITY : rnd() * (hi - lo);
        char why[400];
        Hit hit;
        bool found, same = same_as_brute_force(&bvh, r, 0, tmax, &found, &hit, why, sizeof why);
        ck_assert_msg(same, "random ray %d from (%g, %g, %g) along (%g, %g, %g), tmax %g: %s", k,
                      o.x, o.y, o.z, r.dir.x, r.dir.y, r.dir.z, tmax, why);
        hits += found;
    }
    /* The rays are worth something only if many of them hit and many miss. */
    ck_assert_int_gt(hits, count / 10);
    ck_assert_int_lt(hits, count - count / 10);
    bvh_free(&bvh);
}

/* Loads the scene file at path into scene, without its warnings (a triangle without area
 * skipped), which are not the test's news. */
static void load_scene_file(Scene *scene, const char *path)
{
    FILE *quiet = fopen("/dev/null", "w");
    SceneLoadOptions opts = {.messages = quiet};
    bool loaded = scene_load(scene, path, &opts);
    if (quiet != NULL)
        fclose(quiet);
    ck_assert_msg(loaded, "cannot read %s", path);
}

/* Loads scene file name of scenes/ into scene. */
static void load_scene(Scene *scene, const char *name)
{
    char path[600];
    snprintf(path, sizeof path, "%s/scenes/%s", TOP_DIR, name);
    load_scene_file(scene, path);
}

/* Loads scene file name (in scenes/) and compares, for every step-th pixel, its camera
 * ray and a shadow ray from what it hits towards the first light with brute force. */
static void compare_pixels(const char *name, int step)
{
    progress("comparing the pixels of scenes/%s with brute force", name);
    Scene scene;
    load_scene(&scene, name);
    Bvh bvh;
    ck_assert(bvh_build(&bvh, &scene));
    Camera camera = camera_make(&scene.camera);
    int nx = scene.camera.nx, ny = scene.camera.ny;
    for (int row = 0; row < ny; row += step)
        for (int i = 0; i < nx; i += step) {
            progress_tick(row, ny, "rows");
            /* Pixel (i, row), row counted from the top as --trace-pixel counts it. */
            Ray r = camera_ray(&camera, i + 0.5, ny - 1 - row + 0.5);
            char why[400];
            Hit hit, shadow;
            bool found, blocked,
                same = same_as_brute_force(&bvh, r, 0, INFINITY, &found, &hit, why, sizeof why);
            if (same && found && scene.light_count > 0) {
                Vec3 to = vec3_sub(scene.lights[0].position, hit.point);
                same = same_as_brute_force(&bvh, ray(hit.point, to), 1e-6, 1, &blocked, &shadow,
                                           why, sizeof why);
                if (!same)
                    ck_abort_msg("pixel (%d, %d) of scenes/%s (--trace-pixel %d,%d), the shadow "
                                 "ray towards light 0: %s",
                                 i, row, name, i, row, why);
            }
            ck_assert_msg(same, "pixel (%d, %d) of scenes/%s (--trace-pixel %d,%d): %s", i, row,
                          name, i, row, why);
        }
    bvh_free(&bvh);
    scene_free(&scene);
}

START_TEST(pixels_as_brute_force)
{
    compare_pixels("bvh-ties.scn", 1);
    compare_pixels("demo.scn", 4);
    compare_pixels("bvh-torus.scn", 3);
}
END_TEST

/* Returns a random box: its corners at about scale from the origin, its sides from 0
 * (flat) to about scale. */
static Box rnd_box(double scale)
{
    double lo[3], hi[3];
    for (int a = 0; a < 3; a++) {
        lo[a] = scale * (2 * rnd() - 1);
        hi[a] = rnd() < 0.1 ? lo[a] : lo[a] + scale * rnd();
    }
    return (Box){vec3(lo[0], lo[1], lo[2]), vec3(hi[0], hi[1], hi[2])};
}

/* bvh_node_hit answers for each child exactly as box_hit does for its box, entry and
 * all, on rays chosen to graze: origins on the boxes' planes, rays parallel to a face
 * (d = +-0 on an axis), aimed at a corner, an edge or a face, with tmax at the box's
 * own entry. */
START_TEST(node_hit_is_box_hit)
{
    const double scales[] = {1e-3, 1, 1e3, 1e6};
    long met = 0;
    for (int k = 0; k < 100000; k++) {
        progress_tick(k, 100000, "pairs of boxes");
        double scale = scales[k % 4];
        Box box[2] = {rnd_box(scale), rnd_box(scale)};
        BvhNode node;
        for (int c = 0; c < 2; c++)
            bvh_node_set(&node, c, box[c], (BvhRef){0, 1});
        Vec3 o = vec3_scale(rnd_point(-3, 3), scale);
        if (rnd() < 0.3) /* on a plane of the first box */
            o.x = rnd() < 0.5 ? box[0].lo.x : box[0].hi.x;
        Vec3 target =
            vec3(rnd() < 0.5 ? box[0].lo.x : box[0].hi.x, rnd() < 0.5 ? box[0].lo.y : box[0].hi.y,
                 rnd() < 0.5 ? box[0].lo.z : box[0].hi.z); /* a corner */
        if (rnd() < 0.5)                                   /* a point of an edge or a face */
            target.y = box[0].lo.y + rnd() * (box[0].hi.y - box[0].lo.y);
        Vec3 to = vec3_sub(target, o);
        Vec3 d = rnd() < 0.7 && vec3_length(to) > 0 ? vec3_normalize(to) : rnd_dir();
        if (rnd() < 0.1)
            d.z = rnd() < 0.5 ? 0.0 : -0.0;
        if (d.x == 0 && d.y == 0 && d.z == 0)
            continue;
        BoxRay br = box_ray(ray(o, d));
        double tmin = rnd() < 0.5 ? 0 : 1e-9 * scale, tmax = INFINITY, t, entry[2];
        if (rnd() < 0.3 && box_hit(box[0], &br, tmin, INFINITY, &t))
            tmax = t; /* the interval ends where the box begins */
        else if (rnd() < 0.3)
            tmax = rnd() * 5 * scale;
        int bits = bvh_node_hit(&node, &br, tmin, tmax, entry);
        for (int c = 0; c < 2; c++) {
            bool exact = box_hit(box[c], &br, tmin, tmax, &t);
            ck_assert_msg(exact == (bits >> c & 1) && t == entry[c],
                          "bvh_node_hit: child %d %s (entry %a), box_hit %s (entry %a): "
                          "o (%a, %a, %a) d (%a, %a, %a) t [%a, %a]",
                          c, bits >> c & 1 ? "met" : "missed", entry[c], exact ? "met" : "missed",
                          t, o.x, o.y, o.z, d.x, d.y, d.z, tmin, tmax);
            met += exact;
        }
    }
    ck_assert_msg(met > 10000, "only %ld boxes met: the rays do not test the boxes", met);
}
END_TEST

START_TEST(closest_hit_as_brute_force)
{
    Scene scene;
    random_scene(&scene, 3000, 0.05, 40, 0);
    compare_with_brute_force(&scene, 100000, -0.2, 1.2);
    scene_free(&scene);
    /* Big overlapping triangles: many candidates per ray, many ties broken by order. */
    random_scene(&scene, 300, 0.6, 10, 0);
    compare_with_brute_force(&scene, 20000, -0.2, 1.2);
    scene_free(&scene);
}
END_TEST

START_TEST(modes_0_and_3_as_brute_force)
{
    Scene scene;
    random_scene(&scene, 500, 0.1, 20, 3);
    for (AccelMode mode = ACCEL_BOXED; mode <= ACCEL_BVH; mode += 3) {
        progress("comparing mode %d with brute force for 20000 random rays", mode);
        Accel accel;
        ck_assert(accel_build(&accel, &scene, mode));
        Surfaces s = accel_surfaces(&accel);
        for (int k = 0; k < 20000; k++) {
            progress_tick(k, 20000, "rays");
            Ray r = ray(rnd_point(-0.2, 1.2), rnd_dir());
            Hit want, got;
            char a[160], b[160];
            bool wanted = world_hit(&scene, r, 0, INFINITY, &want);
            bool have = s.hit(s.data, r, 0, INFINITY, &got);
            /* The whole record, point and normal included, is the same. */
            ck_assert_msg(
                have == wanted &&
                    (!wanted ||
                     (got.t == want.t && got.kind == want.kind && got.index == want.index &&
                      got.material == want.material && got.back_face == want.back_face &&
                      vec3_equal(got.point, want.point) && vec3_equal(got.normal, want.normal))),
                "mode %d, random ray %d: finds %s, brute force finds %s", mode, k,
                found_name(&scene, have, &got, a, sizeof a),
                found_name(&scene, wanted, &want, b, sizeof b));
            ck_assert_msg(s.blocked(s.data, r, 0, INFINITY) == wanted,
                          "mode %d, random ray %d: blocked is wrong; brute force finds %s", mode, k,
                          found_name(&scene, wanted, &want, b, sizeof b));
        }
        accel_free(&accel);
    }
    scene_free(&scene);
}
END_TEST

/* Loads mesh name.obj of ../shared/meshes, the course's big meshes, which a starter does
 * not have, into scene (through a scene file written here); false, saying that test
 * skips it, when the mesh is not there. */
static bool load_shared_mesh(Scene *scene, const char *name, const char *test)
{
    char mesh[600], file[100];
    snprintf(mesh, sizeof mesh, "%s/../shared/meshes/%s.obj", TOP_DIR, name);
    FILE *probe = fopen(mesh, "r");
    if (probe == NULL) {
        printf("%s: SKIPPED %s: %s does not exist\n", test, name, mesh);
        return false;
    }
    fclose(probe);
    snprintf(file, sizeof file, "%s.scn", name);
    FILE *f = fopen(file, "w");
    ck_assert_msg(f != NULL, "cannot write %s in the test's folder", file);
    fprintf(f, "c 0 0.1 0.5  0 0 -1  35  35 35  10 10\nm 1 1 1 0 0 0 1 0 0 0\nw %s\n", mesh);
    fclose(f);
    progress("loading %s", mesh);
    load_scene_file(scene, file);
    return true;
}

START_TEST(bunny_as_brute_force)
{
    Scene scene;
    if (!load_shared_mesh(&scene, "bunny", "bunny_as_brute_force"))
        return;
    ck_assert_int_gt(scene.triangle_count, 60000);
    /* The bunny fills about [-0.1, 0.06] x [0.03, 0.19] x [-0.06, 0.06]: rays from
     * around and inside it; brute force costs 70 000 tests a ray, so only a few thousand. */
    compare_with_brute_force(&scene, 3000, -0.12, 0.2);
    scene_free(&scene);
}
END_TEST

/* The BVH of every scene whose geometry the course's checks draw, and of the bunny and
 * Crytek's Sponza when ../shared/meshes has them: every invariant of check_invariants. */
START_TEST(invariants_of_real_scenes)
{
    const char *names[] = {"demo.scn",           "demo-tour.scn",           "bvh-torus.scn",
                           "bvh-ties.scn",       "degenerate-geometry.scn", "glass-mesh.scn",
                           "glass-prism-tir.scn"};
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++) {
        char what[100];
        snprintf(what, sizeof what, "scenes/%s", names[k]);
        Scene scene;
        load_scene(&scene, names[k]);
        check_invariants(&scene, what);
        scene_free(&scene);
    }
    const char *meshes[] = {"bunny", "sponza"};
    for (size_t k = 0; k < sizeof meshes / sizeof meshes[0]; k++) {
        Scene scene;
        if (!load_shared_mesh(&scene, meshes[k], "invariants_of_real_scenes"))
            continue;
        char what[100];
        snprintf(what, sizeof what, "the mesh %s.obj", meshes[k]);
        progress("building and checking the BVH over %s (%d triangles)", meshes[k],
                 scene.triangle_count);
        check_invariants(&scene, what);
        scene_free(&scene);
    }
}
END_TEST

/* Triangle k at x = 4^k, 0.3 * 4^k wide: of the SAH's 16 bins on x, the first holds every
 * triangle but the last one or two, so each split peels off one or two, and the SAH alone
 * would build a chain 86 levels deep (150 triangles: much beyond 4^170 the triangle test's
 * products overflow). The build must stop at BVH_MAX_DEPTH, and a ray straight down onto
 * each triangle must still find it. */
START_TEST(depth_capped_on_a_chain)
{
    enum { COUNT = 150 };
    Scene scene;
    random_scene(&scene, COUNT, 0.05, 0, 0);
    for (int k = 0; k < COUNT; k++) {
        double x = ldexp(1, 2 * k), w = 0.3 * x;
        set_triangle(&scene, k, vec3(x, 0, 0), vec3(x + w, 0, 0), vec3(x, w, 0), 0);
    }
    const char *what = "150 triangles along x, each 4 times as far out and as wide as the last";
    check_invariants(&scene, what);
    Bvh bvh;
    ck_assert(bvh_build(&bvh, &scene));
    for (int k = 0; k < COUNT; k++) {
        double x = ldexp(1, 2 * k), w = 0.3 * x;
        Ray r = ray(vec3(x + 0.1 * w, 0.1 * w, x), vec3(0, 0, -1));
        char why[400], a[160];
        Hit hit;
        bool found, same = same_as_brute_force(&bvh, r, 0, INFINITY, &found, &hit, why, sizeof why);
        ck_assert_msg(same,
                      "the BVH of %s, %d levels deep: the ray straight down onto triangle %d: %s",
                      what, bvh.depth, k, why);
        ck_assert_msg(found && hit.index == k,
                      "the ray straight down onto triangle %d finds %s, even by brute force: the "
                      "test's own mistake",
                      k, found_name(&scene, found, &hit, a, sizeof a));
    }
    bvh_free(&bvh);
    scene_free(&scene);
}
END_TEST

/* Collects the tests of bvh.c and accel.c. */
static Suite *bvh_suite(void)
{
    Suite *s = suite_create("bvh");
    TCase *tc = tcase_create("bvh");
    tcase_set_timeout(tc, 300);
    tcase_add_test(tc, invariants_of_random_soups);
    tcase_add_test(tc, invariants_of_degenerate_sets);
    tcase_add_test(tc, invariants_of_real_scenes);
    tcase_add_test(tc, depth_capped_on_a_chain);
    tcase_add_test(tc, tests_counted_for_the_box_tests_view);
    tcase_add_test(tc, splits_by_the_sah);
    tcase_add_test(tc, traverse_nearer_first_and_stops);
    tcase_add_test(tc, leaf_closest_finds_the_closest);
    tcase_add_test(tc, leaf_any_within_tmin_and_tmax);
    tcase_add_test(tc, node_hit_is_box_hit);
    tcase_add_test(tc, closest_hit_as_brute_force);
    tcase_add_test(tc, pixels_as_brute_force);
    tcase_add_test(tc, modes_0_and_3_as_brute_force);
    tcase_add_test(tc, bunny_as_brute_force);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(bvh_suite)
