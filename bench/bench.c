/* bench.c: how fast part 1.4 loads meshes, builds its BVH and traces fixed sets of rays. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <strings.h>

#include "baseline.h"
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

/* Runs every measurement on mesh m seen from view v with res x res primary rays, against
 * the baseline built at quality. */
static void bench_mesh(BenchMesh *m, View v, int res, BaselineQuality quality)
{
    const Scene *scene = &m->scene;
    /* Both builds twice, in turns, keeping the faster of each. */
    Bvh bvh;
    Baseline *base = NULL;
    double build_ms = INFINITY, base_ms = INFINITY;
    for (int k = 0; k < 2; k++) {
        if (k > 0) {
            bvh_free(&bvh);
            baseline_free(base);
        }
        double start = timing_now(), ms;
        bvh_build(&bvh, scene);
        build_ms = fmin(build_ms, (timing_now() - start) * 1e3);
        base = baseline_build(scene, quality, &ms);
        base_ms = fmin(base_ms, ms);
    }
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

    printf("\n== %s: %d triangles; BVH: %d interior nodes, %d leaves, depth %d\n", m->name,
           scene->triangle_count, bvh.node_count, bvh.node_count + 1, bvh.depth);
    if (m->load_mb_per_s > 0)
        printf("   OBJ load          %8.1f MB/s\n", m->load_mb_per_s);
    else
        printf("   OBJ load              (generated, no file)\n");
    printf("   build             %8.1f ms", build_ms);
    if (base != NULL)
        printf("    Embree %-6s %8.1f ms   ratio raytra/Embree time %.2f", quality_names[quality],
               base_ms, build_ms / base_ms);
    printf("\n   bytes/triangle    %8.1f      (mesh %.1f + BVH %.1f)\n", bytes,
           mesh_bytes / scene->triangle_count, (double)bvh_bytes(&bvh) / scene->triangle_count);
    const char *names[2] = {"primary", "shadow"};
    for (int s = 0; s < 2; s++) {
        const BenchRay *rays = s == 0 ? primary : shadow;
        long count = s == 0 ? np : ns;
        /* raytra with 1 and 2 threads, then Embree likewise, measured in turns. */
        Job job[4];
        Job *jobs[4] = {&job[0], &job[1], &job[2], &job[3]};
        int threads[4] = {1, 2, 1, 2};
        for (int k = 0; k < 4; k++)
            job[k] = (Job){.by = k < 2 ? BY_BVH : BY_BASELINE,
                           .bvh = &bvh,
                           .baseline = base,
                           .rays = rays,
                           .count = count,
                           .shadow = s == 1};
        double rate[4];
        long hits[4];
        timing_rates(jobs, threads, base != NULL ? 4 : 2, rate, hits);
        for (int k = 0; k < 2; k++) {
            printf("   %-7s %d thread%s  %7.2f Mrays/s (%ld rays, %ld %s)", names[s], threads[k],
                   threads[k] > 1 ? "s" : " ", rate[k], count, hits[k], s == 0 ? "hit" : "blocked");
            if (base != NULL)
                printf("   Embree %7.2f Mrays/s (%ld)   raytra/Embree %.2f", rate[k + 2],
                       hits[k + 2], rate[k] / rate[k + 2]);
            printf("\n");
        }
        printf("   %-7s 2 threads / 1 thread: raytra %.2f", names[s], rate[1] / rate[0]);
        if (base != NULL)
            printf(", Embree %.2f", rate[3] / rate[2]);
        printf("\n");
    }
    if (base == NULL)
        printf("   Embree baseline skipped: not built with Embree 3 (libembree-dev)\n");
    baseline_free(base);
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
    printf("raytra bench: part 1.4's BVH; %d x %d primary rays a view; Embree baseline: %s\n", res,
           res, baseline);
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
        bench_mesh(&m, v, res, quality);
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
        bench_mesh(&m, v, res, quality);
        scene_free(&m.scene);
    }
    mesh_sphere(&m, "sphere", 8);
    View v = {vec3(0, 0, 3), vec3(0, 0, -1), vec3(2, 3, 4), 0.8};
    bench_mesh(&m, v, res, quality);
    scene_free(&m.scene);
    if (!bench_brute_force()) {
        fprintf(stderr, "bench: the BVH and brute force hit different numbers of rays\n");
        return 1;
    }
    return 0;
}
