/* partition-le.c: wrong: bvh_split partitions with <= best_bin, so the primitives of the bin
 * just right of the chosen plane go left too, and a split whose right side is that one bin
 * leaves it empty: the tree degenerates (a leaf of more than BVH_MAX_LEAF, halved as it
 * lies). Its images are a correct BVH's: only the tree's statistics tell. */
int bvh_split(Bvh *bvh, int begin, int end, Box box, Box centroids)
{
    double area = box_half_area(box);
    if (!(area > 0))
        return -1;
    int n = end - begin, best_axis = -1, best_bin = 0;
    double best_cost = n * COST_INTERSECT;
    for (int a = 0; a < 3; a++) {
        double lo = vec3_axis(centroids.lo, a), extent = vec3_axis(centroids.hi, a) - lo;
        if (!(extent > 0))
            continue;
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
