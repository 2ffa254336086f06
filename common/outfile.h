/* outfile.h: output files that appear only when complete: write a temporary, then name it. */
#ifndef RAYTRA_OUTFILE_H
#define RAYTRA_OUTFILE_H

#include <stdbool.h>
#include <stdio.h>

#include "diag.h"

typedef struct {
    FILE *file;      /* write the contents here */
    char *path;      /* the name the file gets when committed */
    char *folder;    /* path's folder */
    char *temp_path; /* the named temporary, in the same folder as path; NULL while unnamed */
    bool unnamed;    /* the temporary has no name (O_TMPFILE) until it is complete */
    int unnamed_fd;  /* its descriptor */
    bool linked;     /* committing gave it path itself: no rename needed */
} OutFile;

/* For tests: use a named temporary even where an unnamed one could be made. */
extern bool outfile_avoid_tmpfile;

bool outfile_check(const char *path, Error *err);
bool outfile_open(OutFile *out, const char *path, Error *err);
bool outfile_commit(OutFile *out, Error *err);
void outfile_abort(OutFile *out);

#endif
