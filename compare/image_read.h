/* image_read.h: reading images, PNG, PFM or OpenEXR, as the tools do. */
#ifndef RAYTRA_IMAGE_READ_H
#define RAYTRA_IMAGE_READ_H

#include <stdbool.h>
#include <stdio.h>

#include "diag.h"
#include "image.h"

bool image_read(Image *img, const char *path, Error *err);
bool image_read_exr(Image *img, const char *path, Error *err);
bool image_read_exr_stream(Image *img, FILE *f, const char *name, Error *err);
bool image_exr_size(FILE *f, int *width, int *height, Error *err);

#endif
