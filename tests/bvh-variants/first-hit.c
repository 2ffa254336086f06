/* first-hit.c: wrong: leaf_closest stops the traversal at the first hit it finds, which need
 * not be the closest when leaf boxes overlap. */
static bool leaf_closest(const Bvh *bvh, BvhRef leaf, Ray r, double tmin, double *tmax, void *state)
{
    Closest *c = state;
    for (uint32_t k = leaf.index; k < leaf.index + leaf.count; k++) {
        Hit h;
        if (world_intersect(bvh->scene, bvh->prims[k], r, tmin, *tmax, &h)) {
            *c = (Closest){true, bvh->prims[k], h, c->tmax};
            *tmax = h.t;
            return true;
        }
    }
    return false;
}
