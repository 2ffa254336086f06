/* ties-first.c: a correct BVH unlike raytra's in its ties: leaf_closest tests each primitive up
 * to the closest hit so far, so of surfaces at the same t it keeps the first one the traversal
 * reaches, not the one of the smaller surface number. */
static bool leaf_closest(const Bvh *bvh, BvhRef leaf, Ray r, double tmin, double *tmax, void *state)
{
    Closest *c = state;
    for (uint32_t k = leaf.index; k < leaf.index + leaf.count; k++) {
        Hit h;
        if (world_intersect(bvh->scene, bvh->prims[k], r, tmin, *tmax, &h)) {
            *c = (Closest){true, bvh->prims[k], h, c->tmax};
            *tmax = h.t;
        }
    }
    return false;
}
