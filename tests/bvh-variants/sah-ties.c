/* sah-ties.c: a correct BVH unlike raytra's: the SAH keeps the last of equally cheap splits
 * (<= where raytra has <) and takes a split as cheap as a leaf. */
int bvh_split(Bvh *bvh, int begin, int end, Box box, Box centroids)
{
    enum { BINS = 16 };
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
            if (cost <= best_cost) {
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
