/* baseline_embree.c: Embree 3 traces the benchmark's rays, one at a time, as a yardstick for raytra. */
#include "baseline.h"

#include <embree3/rtcore.h>
#include <stdlib.h>
#include <time.h>

struct Baseline {
    RTCDevice device;
    RTCScene scene;
};

/* Tells whether the baseline was compiled in: yes, with Embree. */
bool baseline_available(void)
{
    return true;
}

/* Returns the seconds of a monotonic clock. */
static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

/* Builds Embree's BVH of scene's triangles at the given quality on one thread. */
Baseline *baseline_build(const Scene *scene, BaselineQuality quality, double *build_ms)
{
    static const enum RTCBuildQuality embree_quality[] = {
        [BASELINE_HIGH] = RTC_BUILD_QUALITY_HIGH,
        [BASELINE_MEDIUM] = RTC_BUILD_QUALITY_MEDIUM,
        [BASELINE_LOW] = RTC_BUILD_QUALITY_LOW,
    };
    Baseline *b = malloc(sizeof *b);
    if (b == NULL)
        return NULL;
    /* One build thread, as raytra's build has. */
    b->device = rtcNewDevice("threads=1");
    double start = now();
    b->scene = rtcNewScene(b->device);
    rtcSetSceneBuildQuality(b->scene, embree_quality[quality]);
    RTCGeometry g = rtcNewGeometry(b->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryBuildQuality(g, embree_quality[quality]);
    /* The same indexed mesh as raytra's, its vertices rounded to float. */
    int n = scene->triangle_count, nv = scene->vertex_count;
    float *v = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                       3 * sizeof(float), (size_t)nv);
    unsigned *index = rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                              3 * sizeof(unsigned), (size_t)n);
    for (int k = 0; k < nv; k++) {
        v[3 * k] = (float)scene->vertices[k].x;
        v[3 * k + 1] = (float)scene->vertices[k].y;
        v[3 * k + 2] = (float)scene->vertices[k].z;
    }
    for (int k = 0; k < n; k++)
        for (int c = 0; c < 3; c++)
            index[3 * k + c] = (unsigned)scene->triangles[k].corner[c];
    rtcCommitGeometry(g);
    rtcAttachGeometry(b->scene, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(b->scene);
    *build_ms = (now() - start) * 1e3;
    return b;
}

/* Traces rays[begin, end) with rtcIntersect1 or rtcOccluded1; returns the hits. */
long baseline_trace(const Baseline *b, const BenchRay *rays, long begin, long end, bool shadow)
{
    struct RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    long hits = 0;
    for (long k = begin; k < end; k++) {
        const BenchRay *br = &rays[k];
        struct RTCRayHit rh = {.ray = {.org_x = (float)br->ray.origin.x,
                                .org_y = (float)br->ray.origin.y,
                                .org_z = (float)br->ray.origin.z,
                                .dir_x = (float)br->ray.dir.x,
                                .dir_y = (float)br->ray.dir.y,
                                .dir_z = (float)br->ray.dir.z,
                                .tnear = 0,
                                .tfar = (float)br->tmax,
                                .mask = ~0u}};
        if (shadow) {
            rtcOccluded1(b->scene, &ctx, &rh.ray);
            hits += rh.ray.tfar < 0;
        } else {
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(b->scene, &ctx, &rh);
            hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        }
    }
    return hits;
}

/* Frees the baseline, if there is one. */
void baseline_free(Baseline *b)
{
    if (b == NULL)
        return;
    rtcReleaseScene(b->scene);
    rtcReleaseDevice(b->device);
    free(b);
}
