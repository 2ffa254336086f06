/* grade_path.h: the disk as the grader meets it: a path's kind, folders, files compared and opened. */
#ifndef RAYTRA_GRADE_PATH_H
#define RAYTRA_GRADE_PATH_H

#include <stdbool.h>
#include <stdio.h>

int path_kind(const char *path);
bool path_make_folder(const char *path);
const char *path_fresh_folder(const char *path, FILE *notes);
char **path_list_folders(const char *folder, int *count);
bool path_same_bytes(const char *a, const char *b);
FILE *path_open_regular(const char *path, const char **kind);

#endif
