/* imgmap.h: the pictures imgdiff draws: heat maps of two images' differences, and thumbnails. */
#ifndef RAYTRA_IMGMAP_H
#define RAYTRA_IMGMAP_H

#include <stdbool.h>

#include "image.h"

double imgmap_pixel_diff(const Image *a, const Image *b, long k, double e[3]);
bool imgmap_write_thumb(const Image *img, bool peaks, PngEncoding encoding, const char *path);
bool imgmap_write_heat(const Image *a, const Image *b, double top, const char *path,
                       const char *thumb_path);
bool imgmap_write_levels(const float *level, int width, int height, double top, const char *path,
                         const char *thumb_path);

#endif
