/* ties-last.c: a correct BVH unlike raytra's in its ties: of surfaces at the same t,
 * leaf_closest keeps the one of the larger surface number, where world_hit keeps the
 * smaller. Its mode 3 differs from its mode 0 exactly where two surfaces tie for a pixel. */
static bool leaf_closest(const Bvh *bvh, BvhRef leaf, Ray r, double tmin, double *tmax, void *state)
{
    Closest *best = state;
    Hit h;
    for (uint32_t k = 0; k < leaf.count; k++) {
        int surface = bvh->prims[leaf.index + k];
        if (!world_intersect(bvh->scene, surface, r, tmin, best->tmax, &h))
            continue;
        bool tie = best->found && h.t == best->hit.t;
        if (best->found && h.t > best->hit.t)
            continue;
        if (tie && surface < best->surface)
            continue;
        best->found = true;
        best->surface = surface;
        best->hit = h;
        *tmax = h.t;
    }
    return false;
}
