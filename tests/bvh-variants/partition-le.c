/* partition-le.c: a wrong BVH: bvh_split partitions with <= where it priced <, so the chosen
 * plane's own bin goes left too and a side may be left empty, and build_node trusts it never
 * to be: a leaf of no primitive, a reference of count 0, poses as a node. On the graded
 * scenes every image is right all the same, but the tree has empty leaves. */
int bvh_split(Bvh *bvh, int begin, int end, Box box, Box centroids)
{
    double area = box_half_area(box);
    if (!(area > 0))
        return -1; /* a point or a line: every split looks free, the SAH cannot choose */
    int n = end - begin, best_axis = -1, best_bin = 0;
    double best_cost = n * COST_INTERSECT;
    for (int a = 0; a < 3; a++) {
        double lo = vec3_axis(centroids.lo, a), extent = vec3_axis(centroids.hi, a) - lo;
        if (!(extent > 0))
            continue; /* every centroid on one plane: nothing to split along this axis */
        Box bin_box[BVH_BINS];
        int bin_count[BVH_BINS] = {0};
        for (int k = 0; k < BVH_BINS; k++)
            bin_box[k] = box_empty();
        for (int k = begin; k < end; k++) {
            int p = bvh->prims[k];
            int bin = bin_of(vec3_axis(bvh->centroids[p], a), lo, BVH_BINS / extent);
            bin_box[bin] = box_union(bin_box[bin], bvh->boxes[p]);
            bin_count[bin]++;
        }
        double right_cost[BVH_BINS];
        Box right = box_empty();
        int right_n = 0;
        for (int k = BVH_BINS - 1; k > 0; k--) {
            right = box_union(right, bin_box[k]);
            right_n += bin_count[k];
            right_cost[k] = box_half_area(right) * right_n;
        }
        Box left = box_empty();
        int left_n = 0;
        for (int k = 1; k < BVH_BINS; k++) {
            left = box_union(left, bin_box[k - 1]);
            left_n += bin_count[k - 1];
            if (left_n == 0 || left_n == n)
                continue;
            double cost = COST_TRAVERSE +
                          (box_half_area(left) * left_n + right_cost[k]) / area * COST_INTERSECT;
            if (cost < best_cost) {
                best_cost = cost;
                best_axis = a;
                best_bin = k;
            }
        }
    }
    if (best_axis < 0)
        return -1;
    double lo = vec3_axis(centroids.lo, best_axis);
    double scale = BVH_BINS / (vec3_axis(centroids.hi, best_axis) - lo);
    int i = begin, j = end - 1;
    while (i <= j) {
        if (bin_of(vec3_axis(bvh->centroids[bvh->prims[i]], best_axis), lo, scale) <= best_bin) {
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
    if (mid < 0) { /* trusts bvh_split never to leave a side empty */
        if (n <= BVH_MAX_LEAF)
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
