/* first-hit-break.c: held out, like first-hit written otherwise: the loop breaks at the first
 * hit and the leaf reports whether it found one, which stops the traversal. */
static bool leaf_closest(const Bvh *bvh, BvhRef leaf, Ray r, double tmin, double *tmax, void *state)
{
    Closest *c = state;
    bool found = false;
    for (uint32_t k = 0; k < leaf.count && !found; k++) {
        Hit h;
        int p = bvh->prims[leaf.index + k];
        found = world_intersect(bvh->scene, p, r, tmin, *tmax, &h);
        if (found) {
            c->found = true, c->surface = p, c->hit = h;
            *tmax = h.t;
        }
    }
    return found;
}
