/* bench.c: how fast part 1.4 loads meshes, builds its BVH and traces fixed sets of rays. */
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <time.h>

#include "baseline.h"
#include "bvh.h"
#include "obj.h"
#include "world.h"

/* Rays traced in one go by a thread before it takes the next batch. */
#define BATCH 4096

/* Returns the seconds of a monotonic clock. */
static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* A benchmark mesh: its triangles as a scene, and how it was obtained. */
typedef struct {
    const char *name;
    Scene scene;
    double load_mb_per_s; /* the OBJ reader's speed; 0 for a generated mesh */
} BenchMesh;

/* Fills scene with the vertices and triangles of mesh, all of material 0. */
static void scene_from_mesh(Scene *scene, const Mesh *mesh)
{
    *scene = (Scene){0};
    scene->vertices = malloc((size_t)mesh->vertex_count * sizeof *scene->vertices);
    memcpy(scene->vertices, mesh->vertices, (size_t)mesh->vertex_count * sizeof *mesh->vertices);
    scene->vertex_count = mesh->vertex_count;
    scene->triangles = malloc((size_t)mesh->triangle_count * sizeof *scene->triangles);
    for (int k = 0; k < mesh->triangle_count; k++) {
        const int *v = mesh->triangles[k];
        scene->triangles[k] = (Face){{v[0], v[1], v[2]}, 0, 0};
    }
    scene->triangle_count = mesh->triangle_count;
    scene->materials = calloc(1, sizeof *scene->materials);
    scene->material_count = 1;
}

/* Loads the OBJ file at path, timing the reader; false when it is not there. */
static bool mesh_load(BenchMesh *m, const char *name, const char *path)
{
    struct stat st;
    if (stat(path, &st) != 0) {
        printf("%-8s SKIPPED: %s does not exist\n", name, path);
        return false;
    }
    Diag diag;
    diag_init(&diag, stderr);
    Mesh mesh;
    double best = INFINITY;
    /* Best of three: the first read also pays for the page cache. */
    for (int k = 0; k < 3; k++) {
        double start = now();
        if (!obj_load(&mesh, path, &diag))
            return false;
        best = fmin(best, now() - start);
        if (k < 2)
            obj_free(&mesh);
    }
    m->name = name;
    m->load_mb_per_s = st.st_size / 1e6 / best;
    scene_from_mesh(&m->scene, &mesh);
    obj_free(&mesh);
    return true;
}

/* Appends the triangle a, b, c (unit vectors) split level times into 4, on the unit
 * sphere, to scene: a geodesic sphere. Each triangle gets three vertices of its own,
 * which weld_vertices then merges. */
static void subdivide(Scene *scene, Vec3 a, Vec3 b, Vec3 c, int level)
{
    if (level == 0) {
        int first = scene->vertex_count;
        scene->vertices[scene->vertex_count++] = a;
        scene->vertices[scene->vertex_count++] = b;
        scene->vertices[scene->vertex_count++] = c;
        scene->triangles[scene->triangle_count++] = (Face){{first, first + 1, first + 2}, 0, 0};
        return;
    }
    Vec3 ab = vec3_normalize(vec3_add(a, b)), bc = vec3_normalize(vec3_add(b, c)),
         ca = vec3_normalize(vec3_add(c, a));
    subdivide(scene, a, ab, ca, level - 1);
    subdivide(scene, ab, b, bc, level - 1);
    subdivide(scene, ca, bc, c, level - 1);
    subdivide(scene, ab, bc, ca, level - 1);
}

/* The vertices that position_compare looks up: qsort passes it no context. */
static const Vec3 *sort_vertices;

/* Returns -1, 0 or 1 as point p comes before, at or after q, ordered by x, then y, then z. */
static int point_order(Vec3 p, Vec3 q)
{
    return p.x != q.x   ? (p.x > q.x) - (p.x < q.x)
           : p.y != q.y ? (p.y > q.y) - (p.y < q.y)
                        : (p.z > q.z) - (p.z < q.z);
}

/* Orders two vertex numbers by the positions of their vertices, then by number. */
static int position_compare(const void *a, const void *b)
{
    int i = *(const int *)a, j = *(const int *)b;
    int order = point_order(sort_vertices[i], sort_vertices[j]);
    return order != 0 ? order : (i > j) - (i < j);
}

/* Merges the vertices of scene that lie at the same point into one, as an OBJ file
 * lists each vertex once, keeping them in the order of their first use. A vertex on an
 * edge is computed alike by both triangles (normalize(a + b) = normalize(b + a)), so the
 * points that should be one are equal. */
static void weld_vertices(Scene *scene)
{
    int n = scene->vertex_count, *order = malloc((size_t)n * sizeof *order),
        *first = malloc((size_t)n * sizeof *first);
    for (int k = 0; k < n; k++)
        order[k] = k;
    sort_vertices = scene->vertices;
    qsort(order, (size_t)n, sizeof *order, position_compare);
    /* first[v]: the lowest-numbered vertex at the point of vertex v, which leads its run. */
    for (int k = 0, lead = 0; k < n; k++) {
        if (k == 0 || point_order(scene->vertices[order[k]], scene->vertices[lead]) != 0)
            lead = order[k];
        first[order[k]] = lead;
    }
    /* The leads are kept in their order, and first[v] becomes the number of v's lead. */
    int count = 0;
    for (int v = 0; v < n; v++) {
        if (first[v] == v) {
            scene->vertices[count] = scene->vertices[v];
            first[v] = count++;
        } else {
            first[v] = first[first[v]];
        }
    }
    for (int k = 0; k < scene->triangle_count; k++)
        for (int c = 0; c < 3; c++)
            scene->triangles[k].corner[c] = first[scene->triangles[k].corner[c]];
    scene->vertex_count = count;
    Vec3 *fit = realloc(scene->vertices, (size_t)count * sizeof *fit);
    scene->vertices = fit != NULL ? fit : scene->vertices;
    free(order);
    free(first);
}

/* Makes a geodesic sphere of radius 1 from an icosahedron split level times:
 * 20 * 4^level triangles. */
static void mesh_sphere(BenchMesh *m, const char *name, int level)
{
    double p = (1 + sqrt(5)) / 2;
    Vec3 v[12] = {{-1, p, 0},  {1, p, 0},  {-1, -p, 0}, {1, -p, 0}, {0, -1, p},  {0, 1, p},
                  {0, -1, -p}, {0, 1, -p}, {p, 0, -1},  {p, 0, 1},  {-p, 0, -1}, {-p, 0, 1}};
    static const int f[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (int k = 0; k < 12; k++)
        v[k] = vec3_normalize(v[k]);
    m->name = name;
    m->load_mb_per_s = 0;
    m->scene = (Scene){0};
    size_t n = (size_t)20 << (2 * level);
    m->scene.vertices = malloc(3 * n * sizeof *m->scene.vertices);
    m->scene.triangles = malloc(n * sizeof *m->scene.triangles);
    for (int k = 0; k < 20; k++)
        subdivide(&m->scene, v[f[k][0]], v[f[k][1]], v[f[k][2]], level);
    weld_vertices(&m->scene);
    m->scene.materials = calloc(1, sizeof *m->scene.materials);
    m->scene.material_count = 1;
}

/* Returns the box of every triangle of scene. */
static Box scene_box(const Scene *scene)
{
    Box b = box_empty();
    for (int k = 0; k < scene->triangle_count; k++) {
        Triangle tri = scene_triangle(scene, k);
        b = box_union(b, box_of_triangle(&tri));
    }
    return b;
}

/* The primary rays of a pinhole camera at eye looking along view, n x n of them over a
 * square field of view of fov radians; y is up. */
static BenchRay *primary_rays(Vec3 eye, Vec3 view, double fov, int n)
{
    BenchRay *rays = malloc((size_t)n * n * sizeof *rays);
    Vec3 w = vec3_normalize(view);
    Vec3 u = vec3_normalize(vec3_cross(w, vec3(0, 1, 0))), v = vec3_cross(u, w);
    double half = tan(fov / 2);
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            double x = ((i + 0.5) / n * 2 - 1) * half, y = ((j + 0.5) / n * 2 - 1) * half;
            Vec3 d = vec3_normalize(vec3_add(w, vec3_add(vec3_scale(u, x), vec3_scale(v, y))));
            rays[(size_t)j * n + i] = (BenchRay){ray(eye, d), INFINITY};
        }
    return rays;
}

/* The shadow rays from the hits of the primary rays towards a point light: from the hit
 * point, moved off the surface by 1e-6 of the scene's size, to the light. */
static BenchRay *shadow_rays(const Bvh *bvh, const BenchRay *primary, long n, Vec3 light,
                             double size, long *count)
{
    BenchRay *rays = malloc((size_t)n * sizeof *rays);
    long m = 0;
    for (long k = 0; k < n; k++) {
        Hit hit;
        long tests = 0;
        if (!bvh_hit(bvh, primary[k].ray, 0, INFINITY, &hit, &tests))
            continue;
        world_complete_hit(bvh->scene, primary[k].ray, &hit);
        Vec3 side = hit.back_face ? vec3_neg(hit.normal) : hit.normal;
        Vec3 p = vec3_add_scaled(hit.point, side, 1e-6 * size);
        Vec3 to = vec3_sub(light, p);
        double d = vec3_length(to);
        rays[m++] = (BenchRay){ray(p, vec3_scale(to, 1 / d)), d};
    }
    *count = m;
    return rays;
}

/* Who traces: raytra's BVH, brute force or the baseline, and which rays. */
typedef enum { BY_BVH, BY_BRUTE_FORCE, BY_BASELINE } Tracer;

typedef struct {
    Tracer by;
    const Bvh *bvh;
    const Baseline *baseline;
    const BenchRay *rays;
    long count;
    bool shadow;
    atomic_long next;
    atomic_long hits;
} Job;

/* Traces batches of the job's rays until none are left. */
static void *trace_worker(void *arg)
{
    Job *job = arg;
    long hits = 0;
    for (;;) {
        long begin = atomic_fetch_add(&job->next, BATCH);
        if (begin >= job->count)
            break;
        long end = begin + BATCH < job->count ? begin + BATCH : job->count;
        if (job->by == BY_BASELINE) {
            hits += baseline_trace(job->baseline, job->rays, begin, end, job->shadow);
            continue;
        }
        for (long k = begin; k < end; k++) {
            const BenchRay *r = &job->rays[k];
            Hit hit;
            long tests = 0;
            if (job->by == BY_BRUTE_FORCE)
                hits += world_hit(job->bvh->scene, r->ray, 0, r->tmax, &hit);
            else if (job->shadow)
                hits += bvh_blocked(job->bvh, r->ray, 0, r->tmax);
            else
                hits += bvh_hit(job->bvh, r->ray, 0, r->tmax, &hit, &tests);
        }
    }
    atomic_fetch_add(&job->hits, hits);
    return NULL;
}

/* Traces all of job's rays once with threads threads; returns the seconds it took. */
static double trace_pass(Job *job, int threads)
{
    atomic_store(&job->next, 0);
    atomic_store(&job->hits, 0);
    pthread_t tid[8];
    double start = now();
    for (int t = 1; t < threads; t++)
        pthread_create(&tid[t], NULL, trace_worker, job);
    trace_worker(job);
    for (int t = 1; t < threads; t++)
        pthread_join(tid[t], NULL);
    return now() - start;
}

/* Traces jobs[0 .. n) with threads[k] threads each, taking turns pass by pass, so that
 * whatever else the machine does slows them alike: at least three passes each, and on
 * until each has run 0.3 s in all (20 passes at most). Sets rate[k] to millions of rays
 * a second of job k's fastest pass, and hits[k] to its hits. */
static void trace_rates(Job **jobs, const int *threads, int n, double *rate, long *hits)
{
    double best[4], total[4] = {0};
    for (int k = 0; k < n; k++)
        best[k] = INFINITY;
    for (int pass = 0; pass < 20; pass++) {
        bool enough = pass >= 3;
        for (int k = 0; k < n; k++) {
            double s = trace_pass(jobs[k], threads[k]);
            best[k] = fmin(best[k], s);
            total[k] += s;
            enough = enough && total[k] >= 0.3;
        }
        if (enough)
            break;
    }
    for (int k = 0; k < n; k++) {
        rate[k] = jobs[k]->count / best[k] / 1e6;
        hits[k] = atomic_load(&jobs[k]->hits);
    }
}

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
        double start = now(), ms;
        bvh_build(&bvh, scene);
        build_ms = fmin(build_ms, (now() - start) * 1e3);
        base = baseline_build(scene, quality, &ms);
        base_ms = fmin(base_ms, ms);
    }
    Box box = scene_box(scene);
    double size = vec3_length(vec3_sub(box.hi, box.lo));
    long np = (long)res * res, ns;
    BenchRay *primary = primary_rays(v.eye, v.view, v.fov, res);
    BenchRay *shadow = shadow_rays(&bvh, primary, np, v.light, size, &ns);
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
        trace_rates(jobs, threads, base != NULL ? 4 : 2, rate, hits);
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
    BenchRay *rays = primary_rays(vec3(0, 0, 3), vec3(0, 0, -1), 0.8, 128);
    long n = 128 * 128;
    Job a = {.by = BY_BVH, .bvh = &bvh, .rays = rays, .count = n};
    Job b = {.by = BY_BRUTE_FORCE, .bvh = &bvh, .rays = rays, .count = n};
    Job *jobs[2] = {&a, &b};
    int threads[2] = {1, 1};
    double rate[2];
    long hits[2];
    trace_rates(jobs, threads, 2, rate, hits);
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
        Box b = scene_box(&m.scene);
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
        Box b = scene_box(&m.scene);
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
