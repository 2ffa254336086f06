/* outfile.h: output files that appear only when complete: write a temporary, then rename. */
#ifndef RAYTRA_OUTFILE_H
#define RAYTRA_OUTFILE_H

#include <stdbool.h>
#include <stdio.h>

#include "diag.h"

typedef struct {
    FILE *file;      /* write the contents here */
    char *path;      /* the name the file gets when committed */
    char *temp_path; /* the temporary, in the same folder as path */
} OutFile;

bool outfile_check(const char *path, Error *err);
bool outfile_open(OutFile *out, const char *path, Error *err);
bool outfile_commit(OutFile *out, Error *err);
void outfile_abort(OutFile *out);

#endif
