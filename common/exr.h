/* exr.h: the OpenEXR file format as raytra writes it: one part of scanlines, floats, ZIP. */
#ifndef RAYTRA_EXR_H
#define RAYTRA_EXR_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "diag.h"

/* The four bytes every OpenEXR file starts with (20000630 as a little-endian integer). */
#define EXR_MAGIC "\x76\x2f\x31\x01"

/* The compressions of the format, by their number in a file's header. */
enum { EXR_NONE, EXR_RLE, EXR_ZIPS, EXR_ZIP, EXR_PIZ, EXR_PXR24, EXR_B44, EXR_B44A, EXR_DWAA, EXR_DWAB };

/* The sample types of a channel, by their number in a file's header. */
enum { EXR_UINT, EXR_HALF, EXR_FLOAT };

/* A channel to write: its samples are first[0], first[step], ... along a row, rows one
 * after the other (step x width floats apart). */
typedef struct {
    const char *name;
    const float *first;
    int step;
} ExrPlane;

/* A header attribute to write: an integer, or text when text is not NULL. */
typedef struct {
    const char *name;
    int value;
    const char *text;
} ExrAttribute;

bool exr_write(FILE *f, int width, int height, const ExrPlane *planes, int plane_count,
               const ExrAttribute *attributes, int attribute_count, Error *err);

#endif
