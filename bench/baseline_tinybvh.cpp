// baseline_tinybvh.cpp: tinybvh's BVH and BVH_SoA trace the benchmark's rays, one at a time.
#define TINYBVH_IMPLEMENTATION
#include "tiny_bvh.h"

#include <chrono>
#include <vector>

extern "C" {
#include "baseline_tinybvh.h"
}

using tinybvh::BVH;
using tinybvh::BVH_SoA;
using tinybvh::bvhvec3;
using tinybvh::bvhvec4;

struct TinyBaseline {
    TinyLayout layout;
    std::vector<bvhvec4> vertices; // the scene's vertices rounded to float, 16 bytes each
    std::vector<uint32_t> corners; // three a triangle, as the scene's faces list them
    BVH bvh;
    BVH_SoA soa;
};

// Tells whether the baselines were compiled in: yes, with tinybvh.
bool tiny_available(void)
{
    return true;
}

// Builds tinybvh's BVH of the scene's triangles in the given layout, on one thread.
TinyBaseline *tiny_build(const Scene *scene, TinyLayout layout, double *build_ms)
{
    auto start = std::chrono::steady_clock::now();
    TinyBaseline *b = new TinyBaseline;
    b->layout = layout;
    int n = scene->triangle_count, nv = scene->vertex_count;
    // The same indexed mesh as raytra's, its vertices rounded to float, as Embree gets it.
    b->vertices.resize((size_t)nv);
    for (int k = 0; k < nv; k++) {
        const Vec3 &v = scene->vertices[k];
        b->vertices[k] = bvhvec4((float)v.x, (float)v.y, (float)v.z, 0);
    }
    b->corners.resize(3 * (size_t)n);
    for (int k = 0; k < n; k++)
        for (int c = 0; c < 3; c++)
            b->corners[3 * (size_t)k + c] = (uint32_t)scene->triangles[k].corner[c];
    // tinybvh builds meshes of 50,000 triangles or more on several threads unless told not to.
    if (layout == TINY_BVH) {
        b->bvh.threadedBuild = false;
        b->bvh.Build(b->vertices.data(), b->corners.data(), (uint32_t)n);
    } else {
        b->soa.bvh.threadedBuild = false;
        b->soa.Build(b->vertices.data(), b->corners.data(), (uint32_t)n);
    }
    *build_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return b;
}

// Returns the benchmark ray br as tinybvh's, and sets *tmax to how far it may go. tinybvh's rays
// start at t = 0, and so do the benchmark's: a shadow ray's start is moved off the surface it
// leaves (rays_shadow), which is how tinybvh takes a tnear.
static tinybvh::Ray tiny_ray(const BenchRay &br, float *tmax)
{
    *tmax = br.tmax < BVH_FAR ? (float)br.tmax : BVH_FAR;
    const Ray &r = br.ray;
    return tinybvh::Ray(bvhvec3((float)r.origin.x, (float)r.origin.y, (float)r.origin.z),
                        bvhvec3((float)r.dir.x, (float)r.dir.y, (float)r.dir.z), *tmax);
}

// Traces rays[begin, end) with Intersect or IsOccluded of the layout built; returns the hits.
template <class Tree>
static long trace(const Tree &tree, const BenchRay *rays, long begin, long end, bool shadow)
{
    long hits = 0;
    for (long k = begin; k < end; k++) {
        float tmax;
        tinybvh::Ray r = tiny_ray(rays[k], &tmax);
        if (shadow) {
            hits += tree.IsOccluded(r);
        } else {
            tree.Intersect(r);
            hits += r.hit.t < tmax;
        }
    }
    return hits;
}

// Traces rays[begin, end) with the baseline's layout; returns the hits or the blocked.
long tiny_trace(const TinyBaseline *b, const BenchRay *rays, long begin, long end, bool shadow)
{
    if (b->layout == TINY_BVH)
        return trace(b->bvh, rays, begin, end, shadow);
    return trace(b->soa, rays, begin, end, shadow);
}

// Frees the baseline, if there is one.
void tiny_free(TinyBaseline *b)
{
    delete b;
}
