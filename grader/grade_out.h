/* grade_out.h: the output folder (--out), prepared for a grading or a merge. */
#ifndef RAYTRA_GRADE_OUT_H
#define RAYTRA_GRADE_OUT_H

#include "grading.h"

bool out_prepare(Grading *g);
void out_release(const char *folder);

#endif
