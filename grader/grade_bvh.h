/* grade_bvh.h: a BVH judged by its shape, from what part 1.4's program prints about it. */
#ifndef RAYTRA_GRADE_BVH_H
#define RAYTRA_GRADE_BVH_H

#include "grading.h"

void bvh_judge(SceneResult *res, const char *output);

#endif
