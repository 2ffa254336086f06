/* exr_header.h: reading an OpenEXR file's header: its attributes, its channel list, its layout. */
#ifndef RAYTRA_EXR_HEADER_H
#define RAYTRA_EXR_HEADER_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "diag.h"
#include "exr.h"

/* A channel of a header. */
typedef struct {
    char name[256];
    int type;                   /* EXR_UINT, EXR_HALF or EXR_FLOAT */
    int x_sampling, y_sampling; /* 1 for every pixel, 2 for every other, ... */
} ExrChannel;

/* A single part's header, as far as raytra reads it. */
typedef struct {
    int parts;           /* 1, or the parts of a multi-part file (nothing else is read) */
    bool deep, tiled;
    int compression;     /* EXR_NONE ... EXR_DWAB, or another number */
    long x0, y0, width, height; /* the data window */
    int channel_count;
    ExrChannel *channels; /* in the order of the file, which is that of each line */
    unsigned char *attributes; /* every attribute as the file holds it */
    size_t attributes_size;
    int64_t table;       /* where the offset table starts: the header's end */
} ExrHeader;

bool exr_read_header(FILE *f, ExrHeader *h, Error *err);
void exr_header_free(ExrHeader *h);
const unsigned char *exr_attribute(const ExrHeader *h, const char *name, const char *type,
                                   uint32_t *size);
bool exr_attribute_int(const ExrHeader *h, const char *name, int32_t *value);
uint32_t exr_le32(const unsigned char *p);

#endif
