/* center-points.c: held out, like centroid-boxes written otherwise: a node's box is grown
 * round the centre of each of its primitives' boxes, so the primitives stick out of it. */
static BvhRef build_node(Bvh *bvh, int begin, int end, int depth, Box *box_out)
{
    Box box = box_empty();
    for (int k = begin; k < end; k++)
        box = box_add_point(box, box_center(bvh->boxes[bvh->prims[k]]));
    *box_out = box;
    if (depth > bvh->depth)
        bvh->depth = depth;
    int n = end - begin;
    int mid = n > 1 && depth < SAH_MAX_DEPTH ? bvh_split(bvh, begin, end, box, box) : -1;
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
