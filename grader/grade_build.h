/* grade_build.h: a program handed in, copied, cleared, given canaries and made. */
#ifndef RAYTRA_GRADE_BUILD_H
#define RAYTRA_GRADE_BUILD_H

#include "grading.h"

char *build_submission(const Grading *g, Submission *s);

#endif
