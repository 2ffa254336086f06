/* centroid-boxes.c: wrong: build_node gives a node the box of its primitives' centroids, not of
 * the primitives, so the traversal misses their edges. */
static BvhRef build_node(BvhBuilder *b, int begin, int end, int depth, Box *box_out)
{
    Box box = box_empty(), centroids = box_empty();
    for (int k = begin; k < end; k++) {
        box = box_union(box, b->boxes[b->prims[k]]);
        centroids = box_add_point(centroids, b->centroids[b->prims[k]]);
    }
    *box_out = centroids;
    if (depth > b->depth)
        b->depth = depth;
    int n = end - begin;
    int mid = n > 1 && depth < SAH_MAX_DEPTH ? bvh_split(b, begin, end, box, centroids) : -1;
    if (mid <= begin || mid >= end) {
        /* No split pays, or the tree is deep: a leaf, unless it would hold too many
         * primitives; then halving them as they are beats no split at all. */
        if (n <= BVH_MAX_LEAF) {
            b->leaf_count++;
            return (BvhRef){(uint32_t)begin, (uint32_t)n};
        }
        mid = begin + n / 2;
    }
    uint32_t self = (uint32_t)b->node_count++;
    Box child_box[2];
    BvhRef left = build_node(b, begin, mid, depth + 1, &child_box[0]); /* node self + 1 */
    BvhRef right = build_node(b, mid, end, depth + 1, &child_box[1]);
    bvh_node_set(&b->nodes[self], 0, child_box[0], left);
    bvh_node_set(&b->nodes[self], 1, child_box[1], right);
    return (BvhRef){self, 0};
}
