/* no-depth-cap.c: wrong: build_node lets the SAH split at any depth, with no SAH_MAX_DEPTH,
 * so a scene of many primitives at one place can make a tree as deep as it has primitives.
 * Its images are a correct BVH's: only the tree's statistics tell. */
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
    int mid = n > 1 ? bvh_split(bvh, begin, end, box, centroids) : -1;
    if (mid <= begin || mid >= end) {
        if (n <= BVH_MAX_LEAF)
            return (BvhRef){(uint32_t)begin, (uint32_t)n};
        mid = begin + n / 2;
    }
    uint32_t self = (uint32_t)bvh->node_count++;
    Box child_box[2];
    BvhRef left = build_node(bvh, begin, mid, depth + 1, &child_box[0]);
    BvhRef right = build_node(bvh, mid, end, depth + 1, &child_box[1]);
    bvh_node_set(&bvh->nodes[self], 0, child_box[0], left);
    bvh_node_set(&bvh->nodes[self], 1, child_box[1], right);
    return (BvhRef){self, 0};
}
