/* image.h: the float RGB image buffer, and reading and writing it as PNG, PFM or OpenEXR. */
#ifndef RAYTRA_IMAGE_H
#define RAYTRA_IMAGE_H

#include <stdbool.h>
#include <stdio.h>

#include "color.h"
#include "diag.h"

/* The largest image raytra makes: the buffer stays well under a gigabyte. */
#define IMAGE_MAX_SIDE 32768
#define IMAGE_MAX_PIXELS (1L << 26)

/* Three floats a pixel, rows from the top, left to right. */
typedef struct {
    int width, height;
    float *pixels;
} Image;

typedef enum {
    IMAGE_FORMAT_UNKNOWN,
    IMAGE_FORMAT_PNG, /* 8-bit RGB, sRGB-encoded (or linear on request) */
    IMAGE_FORMAT_PFM, /* 32-bit float RGB, linear, lossless */
    IMAGE_FORMAT_EXR  /* OpenEXR: 32-bit float RGB, linear, ZIP-compressed (lossless) */
} ImageFormat;

/* How PNG output encodes linear radiance. */
typedef enum {
    PNG_ENCODING_SRGB,  /* clamp to [0, 1], then the sRGB transfer curve */
    PNG_ENCODING_LINEAR /* clamp to [0, 1] and store as is */
} PngEncoding;

/* Tells whether a width x height image is within the limits above. */
static inline bool image_size_ok(long width, long height)
{
    return width >= 1 && height >= 1 && width <= IMAGE_MAX_SIDE && height <= IMAGE_MAX_SIDE &&
           width * height <= IMAGE_MAX_PIXELS;
}

bool image_init(Image *img, int width, int height);
void image_free(Image *img);

/* Stores colour c at column x, row y (row 0 is the top). */
static inline void image_set(Image *img, int x, int y, Color c)
{
    float *p = img->pixels + 3 * ((long)y * img->width + x);
    p[0] = (float)c.r;
    p[1] = (float)c.g;
    p[2] = (float)c.b;
}

/* Returns the colour at column x, row y (row 0 is the top). */
static inline Color image_get(const Image *img, int x, int y)
{
    const float *p = img->pixels + 3 * ((long)y * img->width + x);
    return color(p[0], p[1], p[2]);
}

double image_srgb_encode(double linear);
double image_srgb_decode(double encoded);
int image_encode_8bit(double linear, PngEncoding encoding);
ImageFormat image_format_for_path(const char *path);

bool image_write(const Image *img, const char *path, PngEncoding encoding, Error *err);
bool image_write_png(const Image *img, FILE *f, PngEncoding encoding, Error *err);
bool image_write_pfm(const Image *img, FILE *f, Error *err);
bool image_write_exr(const Image *img, FILE *f, Error *err);

/* Reading: PFM here (the parts' tests read their renders); PNG and OpenEXR in compare/. */
bool image_read_png(Image *img, const char *path, Error *err);
bool image_read_pfm(Image *img, const char *path, Error *err);

#endif
