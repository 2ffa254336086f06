/* exr_rgba.h: reading an OpenEXR image through OpenEXR's C interface to RGBA files. */
#ifndef RAYTRA_EXR_RGBA_H
#define RAYTRA_EXR_RGBA_H

#include <stdbool.h>

#include "diag.h"
#include "image.h"

bool exr_rgba_read(const char *path, Image *img, Error *err);

#endif
