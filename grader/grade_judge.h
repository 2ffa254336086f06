/* grade_judge.h: a submission's image judged against its reference through imgdiff. */
#ifndef RAYTRA_GRADE_JUDGE_H
#define RAYTRA_GRADE_JUDGE_H

#include "grading.h"

char *judge_image_path(const Grading *g, const Submission *s, int k);
void judge_file(const Grading *g, const Submission *s, int k, const char *path,
                const char *missing);

#endif
