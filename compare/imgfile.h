/* imgfile.h: what a file holds, told from its first bytes and header without decoding it. */
#ifndef RAYTRA_IMGFILE_H
#define RAYTRA_IMGFILE_H

#include <stdbool.h>
#include <stdio.h>
#include <sys/stat.h>

#include "diag.h"
#include "image.h"

/* The image formats imgdiff and the grader tell apart. */
typedef enum { IMGFILE_UNKNOWN, IMGFILE_PNG, IMGFILE_PFM, IMGFILE_EXR } ImgFileKind;

const char *imgfile_kind_text(mode_t mode);
FILE *imgfile_fopen(const char *path);
bool imgfile_header(const char *path, ImgFileKind *kind, int *width, int *height, Error *err);
PngEncoding imgfile_encoding(ImgFileKind kind);

#endif
