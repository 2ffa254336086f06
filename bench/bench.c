/* bench.c: how fast part 1.4 loads meshes, builds its BVH and traces fixed sets of rays. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <strings.h>

#include "agree.h"
#include "baseline.h"
#include "baseline_tinybvh.h"
#include "bvh.h"
#include "mesh.h"
#include "rays.h"
#include "timing.h"

/* The baseline's build qualities by name, as the benchmark's third argument gives them. */
static const char *const quality_names[] = {
    [BASELINE_HIGH] = "HIGH", [BASELINE_MEDIUM] = "MEDIUM", [BASELINE_LOW] = "LOW"};

/* Sets *quality to the build quality named name, in any case; false when there is none. */
static bool quality_parse(const char *name, BaselineQuality *quality)
{
    for (int q = 0; q < (int)(sizeof quality_names / sizeof *quality_names); q++)
        if (strcasecmp(name, quality_names[q]) == 0) {
            *quality = (BaselineQuality)q;
            return true;
        }
    return false;
}

/* One view of a mesh: where the camera is and where the light. */
typedef struct {
    Vec3 eye, view, light;
    double fov;
} View;

/* The baselines, in the order they print: Embree 3, tinybvh's binary BVH and its BVH_SoA. */
enum { EMBREE, TINY_BINARY, TINY_SOA, BASELINES };
static const char *const baseline_names[BASELINES] = {"Embree", "BVH", "BVH_SoA"};

/* What one mesh measured, for the summary: one thread, raytra over each baseline (0
 * where the baseline was skipped), and raytra's 2 threads over 1. */
typedef struct {
    const char *name;
    double build[BASELINES];     /* raytra's build time / the baseline's */
    double speed[2][BASELINES];  /* primary, shadow: raytra's rays a second / the baseline's */
    long hits[2][1 + BASELINES]; /* primary, shadow: raytra's hits, then each baseline's */
    double threads[2];           /* primary, shadow: raytra's 2 threads / 1 thread */
} Result;

/* The baselines built for one mesh; NULL where one is skipped. */
typedef struct {
    Baseline *embree;
    TinyBaseline *tiny[2]; /* TINY_BVH, TINY_BVH_SOA */
} Baselines;

/* Tells whether baseline k (EMBREE, TINY_BINARY, TINY_SOA) was built. */
static bool baselines_has(const Baselines *b, int k)
{
    return k == EMBREE ? b->embree != NULL : b->tiny[k - TINY_BINARY] != NULL;
}

/* Frees the baselines of one mesh. */
static void baselines_free(Baselines *b)
{
    baseline_free(b->embree);
    tiny_free(b->tiny[0]);
    tiny_free(b->tiny[1]);
}

/* Builds raytra's BVH of scene into bvh and the baselines into base, each twice, in
 * turns, keeping the faster time of each: ms[0] raytra's, ms[1 + k] baseline k's. */
static void build_all(const Scene *scene, Bvh *bvh, Baselines *base, BaselineQuality quality,
                      double ms[1 + BASELINES])
{
    for (int k = 0; k <= BASELINES; k++)
        ms[k] = INFINITY;
    for (int round = 0; round < 2; round++) {
        if (round > 0) {
            bvh_free(bvh);
            baselines_free(base);
        }
        double start = timing_now(), t;
        bvh_build(bvh, scene);
        ms[0] = fmin(ms[0], (timing_now() - start) * 1e3);
        base->embree = baseline_build(scene, quality, &t);
        ms[1 + EMBREE] = fmin(ms[1 + EMBREE], t);
        for (int l = 0; l < 2; l++) {
            base->tiny[l] = tiny_build(scene, (TinyLayout)l, &t);
            ms[1 + TINY_BINARY + l] = fmin(ms[1 + TINY_BINARY + l], t);
        }
    }
}

/* Prints how many rays each baseline hit (or found blocked) beside raytra's count, and
 * by how much they differ. */
static void print_hits(bool shadow, long count, const long hits[1 + BASELINES],
                       const Baselines *base)
{
    printf("   %-7s %ld rays, %s: raytra %ld", shadow ? "shadow" : "primary", count,
           shadow ? "blocked" : "hit", hits[0]);
    for (int k = 0; k < BASELINES; k++) {
        if (!baselines_has(base, k))
            continue;
        long d = hits[1 + k] - hits[0];
        printf(", %s %ld", baseline_names[k], hits[1 + k]);
        if (d != 0)
            printf(" (%+ld, %+.3f %%)", d, 100.0 * d / (hits[0] > 0 ? hits[0] : 1));
    }
    printf("\n");
}

/* Explains, ray by ray, a tinybvh layout's count that differs from raytra's: how many
 * rays each finds that the other does not, and how many of tinybvh's misses are
 * triangles its Moller-Trumbore test calls parallel to the ray. */
static void explain_hits(const char *kind, const char *name, const Bvh *bvh,
                         const TinyBaseline *tiny, const BenchRay *rays, long count, bool shadow)
{
    Disagreement d = agree_tiny(bvh, tiny, rays, count, shadow);
    printf("   %-7s %s: %ld rays %s in raytra %s in %s (%ld the other way); on %ld of them "
           "raytra's first triangle has |e1.(d x e2)| < %g, which tinybvh takes for parallel\n",
           kind, name, d.missed, shadow ? "blocked" : "that hit", shadow ? "are not" : "miss", name,
           d.extra, d.flat, (double)TINY_PARALLEL);
}

/* Times one set of rays (shadow rays or primary ones): raytra with 1 and 2 threads,
 * Embree likewise, and tinybvh's two layouts with 1 thread, in turns. Prints the hits
 * first, since speeds compare only rays answered alike, then the speeds, and fills
 * out's hits, speed and threads for this kind. */
static void bench_rays(const Bvh *bvh, const Baselines *base, const BenchRay *rays, long count,
                       bool shadow, Result *out)
{
    const char *kind = shadow ? "shadow" : "primary";
    int s = shadow ? 1 : 0;
    Job job[TIMING_MAX_JOBS];
    Job *jobs[TIMING_MAX_JOBS];
    /* slot[k]: baseline k's one-thread job; Embree's two-thread one follows it. */
    int threads[TIMING_MAX_JOBS], n = 0, slot[BASELINES] = {0};
    Job proto = {.bvh = bvh, .rays = rays, .count = count, .shadow = shadow};
    for (int k = -1; k < BASELINES; k++) {
        if (k >= 0 && !baselines_has(base, k))
            continue;
        if (k >= 0)
            slot[k] = n;
        for (int t = 1; t <= (k < TINY_BINARY ? 2 : 1); t++) {
            job[n] = proto, threads[n] = t;
            job[n].by = k < 0 ? BY_BVH : k == EMBREE ? BY_BASELINE : BY_TINYBVH;
            job[n].baseline = base->embree;
            job[n].tiny = k >= TINY_BINARY ? base->tiny[k - TINY_BINARY] : NULL;
            jobs[n] = &job[n];
            n++;
        }
    }
    double rate[TIMING_MAX_JOBS];
    long hits[TIMING_MAX_JOBS];
    timing_rates(jobs, threads, n, rate, hits);
    out->hits[s][0] = hits[0];
    for (int k = 0; k < BASELINES; k++)
        out->hits[s][1 + k] = baselines_has(base, k) ? hits[slot[k]] : 0;
    print_hits(shadow, count, out->hits[s], base);
    for (int k = TINY_BINARY; k < BASELINES; k++)
        if (baselines_has(base, k) && out->hits[s][1 + k] != hits[0])
            explain_hits(kind, baseline_names[k], bvh, base->tiny[k - TINY_BINARY], rays, count,
                         shadow);
    out->threads[s] = rate[1] / rate[0];
    printf("   %-7s 1 thread  %7.2f Mrays/s", kind, rate[0]);
    for (int k = 0; k < BASELINES; k++)
        if (baselines_has(base, k)) {
            out->speed[s][k] = rate[0] / rate[slot[k]];
            printf(";  %s %.2f (raytra/%s %.2f)", baseline_names[k], rate[slot[k]],
                   baseline_names[k], out->speed[s][k]);
        }
    printf("\n   %-7s 2 threads %7.2f Mrays/s (%.2f times 1 thread)", kind, rate[1],
           out->threads[s]);
    if (baselines_has(base, EMBREE)) {
        double one = rate[slot[EMBREE]], two = rate[slot[EMBREE] + 1];
        printf(";  Embree %.2f (%.2f times; raytra/Embree %.2f)", two, two / one, rate[1] / two);
    }
    printf("\n");
}

/* Runs every measurement on mesh m seen from view v with res x res primary rays, against
 * the baselines (Embree's built at quality); fills *out for the summary. */
static void bench_mesh(BenchMesh *m, View v, int res, BaselineQuality quality, Result *out)
{
    const Scene *scene = &m->scene;
    Bvh bvh;
    Baselines base = {0};
    double ms[1 + BASELINES];
    build_all(scene, &bvh, &base, quality, ms);
    Box box = mesh_box(scene);
    double size = vec3_length(vec3_sub(box.hi, box.lo));
    long np = (long)res * res, ns;
    BenchRay *primary = rays_primary(v.eye, v.view, v.fov, res);
    BenchRay *shadow = rays_shadow(&bvh, primary, np, v.light, size, &ns);
    /* The mesh is its vertices and its triangles' indices; the BVH, its nodes and its
     * primitive numbers. */
    double mesh_bytes = (double)scene->vertex_count * sizeof *scene->vertices +
                        (double)scene->triangle_count * sizeof *scene->triangles;
    double bytes = (mesh_bytes + (double)bvh_bytes(&bvh)) / scene->triangle_count;
    *out = (Result){.name = m->name};

    printf("\n== %s: %d triangles; BVH: %d interior nodes, %d leaves, depth %d\n", m->name,
           scene->triangle_count, bvh.node_count, bvh.node_count + 1, bvh.depth);
    if (m->load_mb_per_s > 0)
        printf("   OBJ load          %8.1f MB/s\n", m->load_mb_per_s);
    else
        printf("   OBJ load              (generated, no file)\n");
    printf("   build             %8.1f ms", ms[0]);
    for (int k = 0; k < BASELINES; k++)
        if (baselines_has(&base, k)) {
            out->build[k] = ms[0] / ms[1 + k];
            printf(";  %s%s%s %.1f ms (raytra/%s %.2f)", baseline_names[k], k == 0 ? " " : "",
                   k == 0 ? quality_names[quality] : "", ms[1 + k], baseline_names[k],
                   out->build[k]);
        }
    printf("\n   bytes/triangle    %8.1f      (mesh %.1f + BVH %.1f)\n", bytes,
           mesh_bytes / scene->triangle_count, (double)bvh_bytes(&bvh) / scene->triangle_count);
    bench_rays(&bvh, &base, primary, np, false, out);
    bench_rays(&bvh, &base, shadow, ns, true, out);
    if (!baselines_has(&base, EMBREE))
        printf("   Embree baseline skipped: not built with Embree 3 (libembree-dev)\n");
    if (!baselines_has(&base, TINY_BINARY))
        printf("   tinybvh baselines skipped: built without tiny_bvh.h or a C++ compiler "
               "(TINYBVH=DIR)\n");
    baselines_free(&base);
    free(primary);
    free(shadow);
    bvh_free(&bvh);
}

/* Compares the BVH with brute force on a small mesh: the same rays, single thread. Returns
 * false when the two hit different numbers of rays. */
static bool bench_brute_force(void)
{
    BenchMesh m;
    mesh_sphere(&m, "sphere-5120", 4);
    Bvh bvh;
    bvh_build(&bvh, &m.scene);
    BenchRay *rays = rays_primary(vec3(0, 0, 3), vec3(0, 0, -1), 0.8, 128);
    long n = 128 * 128;
    Job a = {.by = BY_BVH, .bvh = &bvh, .rays = rays, .count = n};
    Job b = {.by = BY_BRUTE_FORCE, .bvh = &bvh, .rays = rays, .count = n};
    Job *jobs[2] = {&a, &b};
    int threads[2] = {1, 1};
    double rate[2];
    long hits[2];
    timing_rates(jobs, threads, 2, rate, hits);
    printf("\n== brute force: geodesic sphere of %d triangles, %ld primary rays, 1 thread\n"
           "   BVH %.2f Mrays/s, brute force %.4f Mrays/s: %.0f times faster (hits %ld %s %ld)\n",
           m.scene.triangle_count, n, rate[0], rate[1], rate[0] / rate[1], hits[0],
           hits[0] == hits[1] ? "=" : "!=", hits[1]);
    free(rays);
    bvh_free(&bvh);
    scene_free(&m.scene);
    return hits[0] == hits[1];
}

/* Prints the ratio x, or a dash where its baseline was skipped. */
static void print_ratio(double x)
{
    if (x > 0)
        printf(" %5.2f", x);
    else
        printf("     -");
}

/* Prints the tables of every mesh's ratios, raytra over each baseline, one thread, and of
 * their hits. */
static void print_summary(const Result *r, int n)
{
    printf("\n== summary: raytra / baseline, one thread (build: time over time; rays: rays a "
           "second over rays a second)\n"
           "   %-8s %-19s %-19s %-19s %s\n"
           "   %-8s %-19s %-19s %-19s %s\n",
           "", "build", "primary", "shadow", "2 threads / 1", "mesh", "Embree BVH   SoA",
           "Embree BVH   SoA", "Embree BVH   SoA", "primary shadow");
    for (int k = 0; k < n; k++) {
        printf("   %-8s", r[k].name);
        for (int b = 0; b < BASELINES; b++)
            print_ratio(r[k].build[b]);
        for (int s = 0; s < 2; s++) {
            printf(" ");
            for (int b = 0; b < BASELINES; b++)
                print_ratio(r[k].speed[s][b]);
        }
        printf("   %5.2f  %5.2f\n", r[k].threads[0], r[k].threads[1]);
    }
    printf("   %-8s %-36s %s\n   %-8s %-36s %s\n", "", "primary rays hit", "shadow rays blocked",
           "mesh", "  raytra   Embree      BVH      SoA", "  raytra   Embree      BVH      SoA");
    for (int k = 0; k < n; k++) {
        printf("   %-8s", r[k].name);
        for (int s = 0; s < 2; s++) {
            printf(" %8ld", r[k].hits[s][0]);
            for (int b = 0; b < BASELINES; b++)
                if (r[k].build[b] > 0)
                    printf(" %8ld", r[k].hits[s][1 + b]);
                else
                    printf("        -");
            printf(s == 0 ? " " : "\n");
        }
    }
}

/* Runs the benchmark: meshes from MESH_DIR (argv[1]) when there, and a generated one, with
 * RES x RES primary rays a view (argv[2]) and the baseline built at QUALITY (argv[3]). */
int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "../../shared/meshes";
    int res = argc > 2 ? atoi(argv[2]) : 1024;
    BaselineQuality quality = BASELINE_HIGH;
    if (argc > 3 && !quality_parse(argv[3], &quality)) {
        fprintf(stderr, "bench: unknown Embree build quality '%s' (HIGH, MEDIUM or LOW)\n",
                argv[3]);
        return 2;
    }
    char baseline[96] = "none (not built with Embree 3)";
    if (baseline_available())
        snprintf(baseline, sizeof baseline,
                 "Embree 3, rtcIntersect1/rtcOccluded1, build quality %s", quality_names[quality]);
    printf("raytra bench: part 1.4's BVH; %d x %d primary rays a view\n"
           "   baseline Embree: %s\n   baselines BVH and BVH_SoA: %s\n",
           res, res, baseline,
           tiny_available() ? "tinybvh's binary BVH and BVH_SoA, Intersect/IsOccluded, "
                              "one build thread"
                            : "none (built without tiny_bvh.h or a C++ compiler)");
    Result results[3];
    int nr = 0;
    char path[4096];
    BenchMesh m;
    snprintf(path, sizeof path, "%s/bunny.obj", dir);
    if (mesh_load(&m, "bunny", path)) {
        /* Front view: the bunny fills [-0.095, 0.061] x [0.033, 0.187] x [-0.062, 0.059]. */
        Box b = mesh_box(&m.scene);
        Vec3 c = box_center(b);
        double s = vec3_length(vec3_sub(b.hi, b.lo));
        View v = {vec3_add(c, vec3(0, 0, 1.2 * s)), vec3(0, 0, -1),
                  vec3_add(c, vec3(0.5 * s, 1.5 * s, 1.0 * s)), 0.7};
        bench_mesh(&m, v, res, quality, &results[nr++]);
        scene_free(&m.scene);
    }
    snprintf(path, sizeof path, "%s/sponza.obj", dir);
    if (mesh_load(&m, "sponza", path)) {
        /* Inside the atrium: a quarter of the way up, looking along its length (x), the
         * light high above the middle. */
        Box b = mesh_box(&m.scene);
        Vec3 c = box_center(b), e = vec3_sub(b.hi, b.lo);
        View v = {vec3(c.x - 0.3 * e.x, b.lo.y + 0.25 * e.y, c.z), vec3(1, -0.1, 0.05),
                  vec3(c.x, b.lo.y + 0.9 * e.y, c.z), 1.4};
        bench_mesh(&m, v, res, quality, &results[nr++]);
        scene_free(&m.scene);
    }
    mesh_sphere(&m, "sphere", 8);
    View v = {vec3(0, 0, 3), vec3(0, 0, -1), vec3(2, 3, 4), 0.8};
    bench_mesh(&m, v, res, quality, &results[nr++]);
    scene_free(&m.scene);
    print_summary(results, nr);
    if (!bench_brute_force()) {
        fprintf(stderr, "bench: the BVH and brute force hit different numbers of rays\n");
        return 1;
    }
    return 0;
}
