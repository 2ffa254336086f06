/* test_bvh.c: the BVH's invariants, and its answers equal to brute force for random rays. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "accel.h"
#include "bvh.h"
#include "testing.h"
#include "world.h"

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

/* What walking a hierarchy found. */
typedef struct {
    const Bvh *bvh;
    int *seen; /* how often each primitive was met in a leaf */
    int nodes, leaves, depth;
} Walk;

/* Checks the subtree at ref, whose box is box, at depth, recursively. */
static void walk(Walk *w, BvhRef ref, Box box, int depth)
{
    if (depth > w->depth)
        w->depth = depth;
    ck_assert_int_lt(depth, BVH_MAX_DEPTH);
    if (ref.count > 0) {
        w->leaves++;
        ck_assert_int_le(ref.count, BVH_MAX_LEAF);
        for (uint32_t k = ref.index; k < ref.index + ref.count; k++) {
            ck_assert_int_lt(k, w->bvh->prim_count);
            uint32_t p = w->bvh->prims[k];
            w->seen[p]++;
            /* Every primitive's own (double) box lies inside its leaf's float box. */
            ck_assert(box_contains(box, bvh_prim_box(w->bvh->scene, p)));
        }
        return;
    }
    ck_assert_int_lt(ref.index, w->bvh->node_count);
    const BvhNode *node = &w->bvh->nodes[ref.index];
    w->nodes++;
    for (int c = 0; c < 2; c++) {
        Box child = bvh_child_box(node, c);
        ck_assert(box_contains(box, child));
        /* Depth first: a first child that is a node comes right after its parent. */
        if (c == 0 && node->count[0] == 0)
            ck_assert_int_eq(node->index[0], ref.index + 1);
        walk(w, bvh_child(node, c), child, depth + 1);
    }
}

/* Builds the BVH of scene and checks every invariant of its structure. */
static void check_invariants(const Scene *scene)
{
    Bvh bvh;
    ck_assert(bvh_build(&bvh, scene));
    int n = scene->sphere_count + scene->triangle_count;
    ck_assert_int_eq(bvh.prim_count, n);
    if (n == 0) {
        ck_assert_int_eq(bvh.node_count, 0);
        ck_assert_int_eq(bvh.leaf_count, 0);
        Hit hit;
        ck_assert(!bvh_hit(&bvh, ray(vec3(0, 0, 0), vec3(0, 0, 1)), 0, INFINITY, &hit));
        ck_assert(!bvh_blocked(&bvh, ray(vec3(0, 0, 0), vec3(0, 0, 1)), 0, INFINITY));
        bvh_free(&bvh);
        return;
    }
    /* A binary tree of L leaves has L - 1 interior nodes, and L <= n. */
    ck_assert_int_le(bvh.leaf_count, n);
    ck_assert_int_eq(bvh.node_count, bvh.leaf_count - 1);
    Walk w = {&bvh, calloc((size_t)n, sizeof(int)), 0, 0, 0};
    walk(&w, bvh.root, bvh.box, 0);
    ck_assert_int_eq(w.nodes, bvh.node_count); /* every node is reached, once */
    ck_assert_int_eq(w.leaves, bvh.leaf_count);
    ck_assert_int_eq(w.depth, bvh.depth);
    for (int p = 0; p < n; p++)
        ck_assert_msg(w.seen[p] == 1, "primitive %d is in %d leaves", p, w.seen[p]);
    free(w.seen);
    bvh_free(&bvh);
}

START_TEST(invariants_of_random_soups)
{
    int sizes[] = {0, 1, 2, 3, 17, 1000, 20000};
    for (size_t k = 0; k < sizeof sizes / sizeof sizes[0]; k++) {
        Scene scene;
        random_scene(&scene, sizes[k], 0.05, sizes[k] / 10, 0);
        check_invariants(&scene);
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
    check_invariants(&scene);
    /* Triangles without area, all on one line. */
    for (int k = 0; k < 500; k++)
        set_triangle(&scene, k, vec3(k, 0, 0), vec3(k + 1, 0, 0), vec3(k + 2, 0, 0), 0);
    check_invariants(&scene);
    /* Points: triangles whose three corners coincide, some at the same place. */
    for (int k = 0; k < 500; k++) {
        Vec3 p = vec3(k % 7, 0, 0);
        set_triangle(&scene, k, p, p, p, 0);
    }
    check_invariants(&scene);
    /* Depth: sizes doubling, each triangle twice as far as the last, a chain for the SAH. */
    for (int k = 0; k < 500; k++) {
        double x = ldexp(1, k % 60);
        set_triangle(&scene, k, vec3(x, 0, 0), vec3(x, 1, 0), vec3(x, 0, 1), 0);
    }
    check_invariants(&scene);
    scene_free(&scene);
    /* Planes only: no primitive in the hierarchy at all. */
    random_scene(&scene, 0, 0.05, 0, 3);
    check_invariants(&scene);
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
    Bvh bvh;
    ck_assert(bvh_build(&bvh, &scene));
    ck_assert_int_eq(bvh_count_tests(&bvh, ray(vec3(0, 0, 0), vec3(0, 0, -1))), 2);
    ck_assert_int_eq(bvh_count_tests(&bvh, ray(vec3(0, 0, 0), vec3(0, 0, 1))), 1);
    bvh_free(&bvh);
    scene_free(&scene);
}
END_TEST

/* Compares the BVH's closest hit and blocked() with brute force for count random rays
 * from points in [lo, hi]^3 on scene, half of them aimed at a point of the scene's box,
 * half in any direction; tmax is random for half of them. */
static void compare_with_brute_force(const Scene *scene, int count, double lo, double hi)
{
    Bvh bvh;
    ck_assert(bvh_build(&bvh, scene));
    Box all = bvh.box;
    int hits = 0, blocked = 0;
    for (int k = 0; k < count; k++) {
        Vec3 o = rnd_point(lo, hi), target = vec3_add(all.lo, vec3(rnd() * (all.hi.x - all.lo.x),
                                                                   rnd() * (all.hi.y - all.lo.y),
                                                                   rnd() * (all.hi.z - all.lo.z)));
        Vec3 to = vec3_sub(target, o);
        Ray r = ray(o, rnd() < 0.5 && vec3_length(to) > 0 ? vec3_normalize(to) : rnd_dir());
        double tmax = rnd() < 0.5 ? INFINITY : rnd() * (hi - lo);
        Hit expected, got;
        bool want = world_hit(scene, r, 0, tmax, &expected);
        bool have = bvh_hit(&bvh, r, 0, tmax, &got);
        ck_assert_int_eq(have, want);
        if (want) {
            hits++;
            ck_assert_msg(got.t == expected.t && got.kind == expected.kind &&
                              got.index == expected.index,
                          "ray %d: BVH found %d %d at t = %.17g, brute force %d %d at %.17g", k,
                          got.kind, got.index, got.t, expected.kind, expected.index, expected.t);
        }
        bool shadow = bvh_blocked(&bvh, r, 0, tmax);
        ck_assert_int_eq(shadow, want);
        blocked += shadow;
    }
    /* The rays are worth something only if many of them hit and many miss. */
    ck_assert_int_gt(hits, count / 10);
    ck_assert_int_lt(hits, count - count / 10);
    ck_assert_int_eq(blocked, hits);
    bvh_free(&bvh);
}

/* Returns a random float box: its corners at about scale from the origin, its sides
 * from 0 (flat) to about scale. */
static Box rnd_float_box(double scale)
{
    double lo[3], hi[3];
    for (int a = 0; a < 3; a++) {
        lo[a] = (float)(scale * (2 * rnd() - 1));
        hi[a] = rnd() < 0.1 ? lo[a] : (float)(lo[a] + scale * rnd());
    }
    return (Box){vec3(lo[0], lo[1], lo[2]), vec3(hi[0], hi[1], hi[2])};
}

/* The float test of two boxes against the exact slab test in double, on rays chosen to
 * graze: origins on the boxes' planes or at no float, rays parallel to a face, aimed at
 * a corner, an edge or a face, with tmax at the box's own entry. Wherever the double test
 * meets a box, so must the float test; and it may meet more, but rarely. */
START_TEST(float_test_is_conservative)
{
    Bvh bvh = {.float_safe = true};
    long met = 0, extra = 0, count = 0; /* of the rays in random directions */
    const double scales[] = {1e-3, 1, 1e3, 1e6};
    for (int k = 0; k < 400000; k++) {
        double scale = scales[k % 4];
        Box box[2] = {rnd_float_box(scale), rnd_float_box(scale)};
        BvhNode node = {0};
        for (int c = 0; c < 2; c++) /* float boxes already: stored as they are */
            bvh_node_set_child(&node, c, box[c], (BvhRef){0, 1});
        Vec3 o = vec3_scale(rnd_point(-3, 3), scale);
        if (rnd() < 0.3) /* on a plane of the first box */
            o.x = rnd() < 0.5 ? box[0].lo.x : box[0].hi.x;
        Vec3 target = vec3(rnd() < 0.5 ? box[0].lo.x : box[0].hi.x,
                           rnd() < 0.5 ? box[0].lo.y : box[0].hi.y,
                           rnd() < 0.5 ? box[0].lo.z : box[0].hi.z); /* a corner */
        if (rnd() < 0.5) /* a point of an edge or a face */
            target.y = box[0].lo.y + rnd() * (box[0].hi.y - box[0].lo.y);
        Vec3 to = vec3_sub(target, o);
        bool aimed = rnd() < 0.7 && vec3_length(to) > 0;
        Vec3 d = aimed ? vec3_normalize(to) : rnd_dir();
        if (rnd() < 0.1)
            d.z = rnd() < 0.5 ? 0.0 : -0.0;
        if (d.x == 0 && d.y == 0 && d.z == 0)
            continue;
        Ray r = ray(o, d);
        BoxRay br = box_ray(r);
        double tmin = rnd() < 0.5 ? 0 : 1e-9 * scale, tmax = INFINITY, t;
        if (rnd() < 0.3 && box_hit(box[0], &br, tmin, INFINITY, &t))
            tmax = t; /* the interval ends where the box begins */
        else if (rnd() < 0.3)
            tmax = rnd() * 5 * scale;
        int bits = bvh_children_hit(&bvh, &node, r, tmin, tmax);
        for (int c = 0; c < 2; c++) {
            bool exact = box_hit(box[c], &br, tmin, tmax, &t);
            if (exact)
                ck_assert_msg(bits >> c & 1,
                              "box %d missed: o (%a, %a, %a) d (%a, %a, %a) t [%a, %a]", c,
                              o.x, o.y, o.z, d.x, d.y, d.z, tmin, tmax);
            if (aimed)
                continue;
            met += exact;
            extra += !exact && (bits >> c & 1);
            count++;
        }
    }
    /* The margin is about 2^-20 of t: a ray in a random direction rarely passes so close. */
    ck_assert_msg(met > 1000 && extra * 10 < met, "of %ld boxes, %ld met, %ld by the float test alone",
                  count, met, extra);
}
END_TEST

/* A ray whose origin or direction is beyond what floats can hold, or whose tmin is
 * negative, meets every box: slow, but never wrong. */
START_TEST(float_test_out_of_range)
{
    Bvh bvh = {.float_safe = true};
    BvhNode node = {.bounds = {{0, 10, 1, 11}, {0, 10, 1, 11}, {0, 10, 1, 11}}};
    ck_assert_int_eq(bvh_children_hit(&bvh, &node, ray(vec3(5, 5, -5), vec3(0, 0, 1)), 0, 1), 0);
    ck_assert_int_eq(bvh_children_hit(&bvh, &node, ray(vec3(0.5, 0.5, -5), vec3(0, 0, 1)), 0,
                                      INFINITY),
                     1);
    ck_assert_int_eq(bvh_children_hit(&bvh, &node, ray(vec3(0x1p60, 5, -5), vec3(0, 0, 1)), 0, 1),
                     3);
    ck_assert_int_eq(bvh_children_hit(&bvh, &node, ray(vec3(5, 5, -5), vec3(0x1p-60, 0, 1)), 0, 1),
                     3);
    ck_assert_int_eq(bvh_children_hit(&bvh, &node, ray(vec3(5, 5, -5), vec3(0, 0, 1)), -1, 1), 3);
    bvh.float_safe = false;
    ck_assert_int_eq(bvh_children_hit(&bvh, &node, ray(vec3(5, 5, -5), vec3(0, 0, 1)), 0, 1), 3);
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
        Accel accel;
        ck_assert(accel_build(&accel, &scene, mode));
        Surfaces s = accel_surfaces(&accel);
        for (int k = 0; k < 20000; k++) {
            Ray r = ray(rnd_point(-0.2, 1.2), rnd_dir());
            Hit expected, got;
            bool want = world_hit(&scene, r, 0, INFINITY, &expected);
            ck_assert_int_eq(s.hit(s.data, r, 0, INFINITY, &got), want);
            ck_assert_int_eq(s.blocked(s.data, r, 0, INFINITY), want);
            if (want) {
                /* The whole record, point and normal included, is the same. */
                ck_assert(got.t == expected.t && got.kind == expected.kind &&
                          got.index == expected.index && got.material == expected.material &&
                          got.back_face == expected.back_face);
                ck_assert_vec3_near(got.point, expected.point, 0);
                ck_assert_vec3_near(got.normal, expected.normal, 0);
            }
        }
        accel_free(&accel);
    }
    scene_free(&scene);
}
END_TEST

START_TEST(bunny_as_brute_force)
{
    const char *mesh = TOP_DIR "/../shared/meshes/bunny.obj";
    FILE *probe = fopen(mesh, "r");
    if (probe == NULL) {
        printf("bunny_as_brute_force: SKIPPED: %s does not exist\n", mesh);
        return;
    }
    fclose(probe);
    FILE *f = fopen("bunny.scn", "w");
    fprintf(f, "c 0 0.1 0.5  0 0 -1  35  35 35  10 10\nm 1 1 1 0 0 0 1 0 0 0\nw %s\n", mesh);
    fclose(f);
    Scene scene;
    SceneLoadOptions opts = {0};
    ck_assert(scene_load(&scene, "bunny.scn", &opts));
    ck_assert_int_gt(scene.triangle_count, 60000);
    /* The bunny fills about [-0.1, 0.06] x [0.03, 0.19] x [-0.06, 0.06]: rays from
     * around and inside it; brute force costs 70 000 tests a ray, so only a few thousand. */
    compare_with_brute_force(&scene, 3000, -0.12, 0.2);
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
    tcase_add_test(tc, tests_counted_for_the_box_tests_view);
    tcase_add_test(tc, float_test_is_conservative);
    tcase_add_test(tc, float_test_out_of_range);
    tcase_add_test(tc, closest_hit_as_brute_force);
    tcase_add_test(tc, modes_0_and_3_as_brute_force);
    tcase_add_test(tc, bunny_as_brute_force);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(bvh_suite)
