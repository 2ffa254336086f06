/* exr_read.h: reading the pixels of the OpenEXR scanline files zlib decompresses, whose headers
 * exr_header.h reads. */
#ifndef RAYTRA_EXR_READ_H
#define RAYTRA_EXR_READ_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "diag.h"
#include "exr_header.h"

/* Where the samples of a channel go: first[0], first[step], ... along a row, rows
 * step x width floats apart; first NULL for a channel not read. */
typedef struct {
    float *first;
    int step;
} ExrTarget;

bool exr_decodes(const ExrHeader *h);
bool exr_read_pixels(FILE *f, const ExrHeader *h, const ExrTarget *targets, Error *err);
float exr_half_to_float(uint16_t h);

#endif
