/* grade_part.h: finding the repository and the part, reading renders.txt. */
#ifndef RAYTRA_GRADE_PART_H
#define RAYTRA_GRADE_PART_H

#include <stdbool.h>

#include "grade.h"

char *part_find_top(const char *argv0, char **tools_build);
char **part_list_folders(const char *folder, int *count);
void part_free_names(char **names, int count);
char *part_find(const char *top, const char *part);
bool part_read_renders(Grading *g, const char *top);
bool part_show_references(Grading *g);

#endif
