/* leaf-skips-last.c: held out, a mistake the gallery does not have: leaf_closest tests all of
 * a leaf's primitives but its last, so surfaces go missing wherever they end a leaf. */
static bool leaf_closest(const Bvh *bvh, BvhRef leaf, Ray r, double tmin, double *tmax, void *state)
{
    Closest *c = state;
    for (uint32_t k = leaf.index; k + 1 < leaf.index + leaf.count; k++) {
        Hit h;
        if (world_intersect(bvh->scene, bvh->prims[k], r, tmin, c->tmax, &h) &&
            (!c->found || h.t < c->hit.t)) {
            *c = (Closest){true, bvh->prims[k], h, c->tmax};
            *tmax = h.t;
        }
    }
    return false;
}
