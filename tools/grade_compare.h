/* grade_compare.h: judging a submitted image: a file handed in, compared by imgdiff. */
#ifndef RAYTRA_GRADE_COMPARE_H
#define RAYTRA_GRADE_COMPARE_H

#include <stdbool.h>

#include "grade.h"

bool compare_handed_in(const Render *r, SceneResult *res, const char *path);
void compare_image(const Grading *g, const Submission *s, int k, const char *image);

#endif
