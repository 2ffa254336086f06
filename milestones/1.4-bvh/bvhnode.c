/* bvhnode.c: a BVH node's float boxes, and the float ray that tests them without missing a box.
 *
 * The bound is pbrt-v4's (Pharr, Jakob, Humphreys, "Physically Based Rendering", 4th ed.,
 * 6.8.2; Ize, "Robust BVH Ray Traversal", JCGT 2(2), 2013): with u = 2^-24 and gamma(n)
 * = n u / (1 - n u), a slab's t computed as fl(fl(face - o) * fl(1/d)) is its exact t
 * times 1 + theta, |theta| <= gamma(3), so an exit grown by 1 + 2 gamma(3) is never before
 * its entry when the exact exit is not. raytra grows exits by 2^-20 = 16 u (1/d of the
 * far faces, and tmax), which covers that and its own roundings. Rounding raytra's double
 * origin to float moves a t by at most s = |o - o_float| |1/d| an axis: the test is
 * t0 <= t1 + 3 s + FLT_MIN (products below float's normal range). The boxes are rounded
 * outwards. Out of range (a coordinate past 2^60, |1/d| past 2^+-60, tmin < 0) every box
 * is met. docs/1.4-bvh.md works it through; tests/test_bvh.c tries it on 400 000 boxes. */
#include "bvhnode.h"

#include <float.h>
#include <math.h>

/* Returns a float no greater than x: x rounded, and moved down past x when rounding
 * went up (by 2^-23 of x, at least one float step; 2^-149 for the smallest floats). */
static float box_float_below(double x)
{
    float f = (float)x;
    return (double)f <= x ? f : (float)(x - fabs(x) * 0x1p-23 - 0x1p-149);
}

/* Stores child k of node: where it is, and its box rounded outwards to floats. */
void bvh_node_set(BvhNode *node, int k, Box box, BvhRef ref)
{
    double lo[3] = {box.lo.x, box.lo.y, box.lo.z}, hi[3] = {box.hi.x, box.hi.y, box.hi.z};
    for (int a = 0; a < 3; a++) {
        node->bound[0][a][k] = box_float_below(lo[a]);
        node->bound[1][a][k] = -box_float_below(-hi[a]);
    }
    node->child[k] = ref;
}

/* Returns the box of child k of node, as doubles: exactly its float box. */
Box bvh_node_box(const BvhNode *node, int k)
{
    return (Box){vec3(node->bound[0][0][k], node->bound[0][1][k], node->bound[0][2][k]),
                 vec3(node->bound[1][0][k], node->bound[1][1][k], node->bound[1][2][k])};
}

/* Tells whether every coordinate of box is within +-2^60, where the float test holds. */
bool box_float_in_range(Box box)
{
    return vec3_max_abs(box.lo) <= 0x1p60 && vec3_max_abs(box.hi) <= 0x1p60;
}

/* excerpt: box-float-ray-make */
/* Makes ray r, from tmin on, ready for bvh_node_hit: the slack is 3 s + FLT_MIN. An axis
 * with d = 0 adds nothing to s: rounding o crosses no plane (or makes 0 * inf, NaN, which
 * the test leaves out). Out of range, every t is 0 and the slack infinite. */
FloatRay box_float_ray(Ray r, double tmin, bool in_range)
{
    FloatRay fr = {.tmin = (float)tmin};
    double o[3] = {r.origin.x, r.origin.y, r.origin.z}, d[3] = {r.dir.x, r.dir.y, r.dir.z};
    double shift = 0;
    in_range = in_range && tmin >= 0;
    for (int a = 0; a < 3; a++) {
        double inv = 1 / d[a];
        float of = (float)o[a], near = (float)inv, far = (float)(inv * (1 + 0x1p-20));
        fr.origin[a][0] = fr.origin[a][1] = of;
        fr.inv_near[a][0] = fr.inv_near[a][1] = near;
        fr.inv_far[a][0] = fr.inv_far[a][1] = far;
        fr.near[a] = signbit(d[a]) ? 1 : 0; /* towards -x, it enters at hi */
        fr.far[a] = 1 - fr.near[a];
        in_range = in_range && fabs(o[a]) <= 0x1p60;
        if (d[a] != 0) {
            double moved = fabs(o[a] - of) * fabs(inv);
            shift = moved > shift ? moved : shift;
            in_range = in_range && fabs(inv) >= 0x1p-60 && fabs(inv) <= 0x1p60;
        }
    }
    fr.slack = (float)(3 * shift) + FLT_MIN;
    if (!in_range)
        fr = (FloatRay){.far = {1, 1, 1}, .slack = INFINITY};
    return fr;
}
/* end excerpt: box-float-ray-make */
