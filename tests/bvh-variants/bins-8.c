/* bins-8.c: a correct BVH unlike raytra's: the SAH over 8 bins, not 16, with leaves of up to
 * 2 primitives (build_node), not 8. */
int bvh_split(Bvh *bvh, int begin, int end, Box box, Box centroids)
{
    enum { BINS = 8 };
    double area = box_half_area(box);
    if (!(area > 0))
        return -1;
    int n = end - begin, best_axis = -1, best_plane = 0;
    double best_cost = n, lo[3], scale[3];
    for (int a = 0; a < 3; a++) {
        lo[a] = vec3_axis(centroids.lo, a);
        double extent = vec3_axis(centroids.hi, a) - lo[a];
        scale[a] = extent > 0 ? BINS / extent : 0;
        if (scale[a] == 0)
            continue;
        Box bins[BINS];
        int counts[BINS] = {0};
        for (int k = 0; k < BINS; k++)
            bins[k] = box_empty();
        for (int k = begin; k < end; k++) {
            Vec3 c = bvh->centroids[bvh->prims[k]];
            int bin = (int)((vec3_axis(c, a) - lo[a]) * scale[a]);
            bin = bin < 0 ? 0 : bin >= BINS ? BINS - 1 : bin;
            bins[bin] = box_union(bins[bin], bvh->boxes[bvh->prims[k]]);
            counts[bin]++;
        }
        /* Each plane p between bin p - 1 and bin p, its two sides gathered afresh. */
        for (int p = 1; p < BINS; p++) {
            Box left = box_empty(), right = box_empty();
            int left_n = 0;
            for (int k = 0; k < BINS; k++) {
                if (k < p)
                    left = box_union(left, bins[k]), left_n += counts[k];
                else
                    right = box_union(right, bins[k]);
            }
            if (left_n == 0 || left_n == n)
                continue;
            double cost = 1 + (box_half_area(left) * left_n + box_half_area(right) * (n - left_n)) / area;
            if (cost < best_cost) {
                best_cost = cost;
                best_axis = a;
                best_plane = p;
            }
        }
    }
    if (best_axis < 0)
        return -1;
    int i = begin, j = end - 1;
    while (i <= j) {
        Vec3 c = bvh->centroids[bvh->prims[i]];
        int bin = (int)((vec3_axis(c, best_axis) - lo[best_axis]) * scale[best_axis]);
        bin = bin < 0 ? 0 : bin >= BINS ? BINS - 1 : bin;
        if (bin < best_plane) {
            i++;
        } else {
            int swap = bvh->prims[i];
            bvh->prims[i] = bvh->prims[j];
            bvh->prims[j--] = swap;
        }
    }
    return i;
}
static BvhRef build_node(Bvh *bvh, int begin, int end, int depth, Box *box_out)
{
    Box box = box_empty(), centroids = box_empty();
    for (int k = begin; k < end; k++) {
        box = box_union(box, bvh->boxes[bvh->prims[k]]);
        centroids = box_add_point(centroids, bvh->centroids[bvh->prims[k]]);
    }
    *box_out = box;
    if (depth > bvh->depth)
        bvh->depth = depth;
    int n = end - begin;
    int mid = n > 1 && depth < SAH_MAX_DEPTH ? bvh_split(bvh, begin, end, box, centroids) : -1;
    if (mid <= begin || mid >= end) {
        /* No split pays, or the tree is deep: a leaf, unless it would hold too many
         * primitives; then halving them as they are beats no split at all. */
        if (n <= 2)
            return (BvhRef){(uint32_t)begin, (uint32_t)n};
        mid = begin + n / 2;
    }
    uint32_t self = (uint32_t)bvh->node_count++;
    Box child_box[2];
    BvhRef left = build_node(bvh, begin, mid, depth + 1, &child_box[0]); /* node self + 1 */
    BvhRef right = build_node(bvh, mid, end, depth + 1, &child_box[1]);
    bvh_node_set(&bvh->nodes[self], 0, child_box[0], left);
    bvh_node_set(&bvh->nodes[self], 1, child_box[1], right);
    return (BvhRef){self, 0};
}
