/* grade_bvh.c: a BVH judged by its shape, from what part 1.4's program prints about it. */
#include "grade_bvh.h"

#include <stdio.h>
#include <string.h>

#include "bvh.h"
#include "grade_verdict.h"

/* Judges the BVH that a run's output tells of, in the last line of part 1.4's report
 * ("BVH of N primitives: X interior nodes, L leaves (E empty), depth D"), once its image
 * has passed: a BVH that draws right can still break what a traversal relies on, or the
 * part's rules. Fails res, saying what is wrong and what to look at, when the tree has a
 * leaf of no primitive, more interior nodes than n - 1, or more levels than a build that
 * stops the SAH at SAH_MAX_DEPTH and halves below can make: SAH_MAX_DEPTH + ceil(log2 n),
 * and never more than BVH_MAX_DEPTH.
 * Judges nothing when the image did not pass or the output has no such line (modes 0 and
 * 1 build no BVH). */
void bvh_judge(SceneResult *res, const char *output)
{
    const char *line = NULL;
    for (const char *p = output; p != NULL && (p = strstr(p, "BVH of ")) != NULL; p++)
        line = p;
    int n, nodes, leaves, empty, depth, most = SAH_MAX_DEPTH;
    if (res->verdict != VERDICT_PASS || line == NULL ||
        /* at most 9 digits a number: a student's output, never read past an int */
        sscanf(line, "BVH of %9d primitives: %9d interior nodes, %9d leaves (%9d empty), depth %9d",
               &n, &nodes, &leaves, &empty, &depth) != 5)
        return;
    for (long halves = 1; halves < n && most < BVH_MAX_DEPTH; halves *= 2)
        most++;
    if (empty > 0)
        verdict_set(res, VERDICT_FAIL,
                    "the image is right, but the BVH has %d empty leaves (leaves of no "
                    "primitive; %d leaves over %d primitives in all): does bvh_split's "
                    "partition put the primitives of the chosen plane's own bin on the side the "
                    "SAH counted them on (< the plane's bin, not <=)? build_node must never "
                    "build a subtree over no primitives",
                    empty, leaves, n);
    else if (n > 0 && nodes > n - 1)
        verdict_set(res, VERDICT_FAIL,
                    "the image is right, but the BVH has %d interior nodes over %d primitives, "
                    "more than the n - 1 = %d a tree whose every leaf holds a primitive can "
                    "have: does build_node take a node's entry before it knows it will split?",
                    nodes, n, n - 1);
    else if (depth > most)
        verdict_set(res, VERDICT_FAIL,
                    "the image is right, but the BVH is %d levels deep, more than the %d "
                    "(SAH_MAX_DEPTH + log2 of its %d primitives, at most BVH_MAX_DEPTH, %d, "
                    "which bvh_traverse's stack holds) of a build that stops asking the SAH "
                    "at SAH_MAX_DEPTH: does build_node then halve its primitives as they lie?",
                    depth, most, n, BVH_MAX_DEPTH);
}
