/* grade_section.h: a submission's section of the report: its build, and a block a scene. */
#ifndef RAYTRA_GRADE_SECTION_H
#define RAYTRA_GRADE_SECTION_H

#include <stdio.h>

#include "grading.h"

char *section_command(const Submission *s, const SceneResult *res);
void section_write(FILE *f, const Grading *g, int i);

#endif
