/* median-one.c: a correct BVH unlike raytra's: object-median splits on the centroids' longest
 * axis, down to one primitive a leaf; no SAH. */
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
    if (end - begin == 1)
        return (BvhRef){(uint32_t)begin, 1};
    /* The longest axis of the centroids, and the median along it by quickselect. */
    Vec3 extent = vec3_sub(centroids.hi, centroids.lo);
    int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    int mid = begin + (end - begin) / 2, lo = begin, hi = end - 1;
    while (lo < hi) {
        double pivot = vec3_axis(bvh->centroids[bvh->prims[(lo + hi) / 2]], axis);
        int i = lo, j = hi;
        while (i <= j) {
            if (vec3_axis(bvh->centroids[bvh->prims[i]], axis) < pivot) {
                i++;
            } else if (vec3_axis(bvh->centroids[bvh->prims[j]], axis) > pivot) {
                j--;
            } else {
                int swap = bvh->prims[i];
                bvh->prims[i++] = bvh->prims[j];
                bvh->prims[j--] = swap;
            }
        }
        if (mid <= j)
            hi = j;
        else if (mid >= i)
            lo = i;
        else
            break;
    }
    uint32_t self = (uint32_t)bvh->node_count++;
    Box child_box[2];
    BvhRef left = build_node(bvh, begin, mid, depth + 1, &child_box[0]);
    BvhRef right = build_node(bvh, mid, end, depth + 1, &child_box[1]);
    bvh_node_set(&bvh->nodes[self], 0, child_box[0], left);
    bvh_node_set(&bvh->nodes[self], 1, child_box[1], right);
    return (BvhRef){self, 0};
}
