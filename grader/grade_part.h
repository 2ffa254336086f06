/* grade_part.h: the part graded: its folder, its references made and shown, their canaries; points. */
#ifndef RAYTRA_GRADE_PART_H
#define RAYTRA_GRADE_PART_H

#include <stdbool.h>

#include "grading.h"

bool part_find_top(Grading *g);
bool part_find(Grading *g, const char *part);
bool part_render_hidden(Grading *g);
bool part_show_references(Grading *g);
void part_make_canaries(Grading *g);
double part_points(const Grading *g, const Submission *s, double *max);

#endif
