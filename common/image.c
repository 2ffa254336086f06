/* image.c: the float image buffer, the sRGB transfer curve, and choosing a file format. */
#include "image.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "outfile.h"

/* Makes img a black width x height image; false (img empty) when too large or no memory. */
bool image_init(Image *img, int width, int height)
{
    img->width = 0;
    img->height = 0;
    img->pixels = NULL;
    if (!image_size_ok(width, height))
        return false;
    float *pixels = calloc((size_t)width * (size_t)height * 3, sizeof *pixels);
    if (pixels == NULL)
        return false;
    img->width = width;
    img->height = height;
    img->pixels = pixels;
    return true;
}

/* Frees the pixels and empties img; harmless on an empty (zeroed) image. */
void image_free(Image *img)
{
    free(img->pixels);
    img->pixels = NULL;
    img->width = 0;
    img->height = 0;
}

/* Returns the sRGB-encoded value of a linear one (IEC 61966-2-1): a straight segment
 * near black, where a pure power curve would be infinitely steep, then a 1/2.4 power;
 * the pieces meet at 0.0031308 (encoded 0.04045, to within 3e-8). */
double image_srgb_encode(double linear)
{
    if (linear <= 0.0031308)
        return 12.92 * linear;
    return 1.055 * pow(linear, 1.0 / 2.4) - 0.055;
}

/* Returns the 8-bit code a PNG stores for a linear value: NaN becomes 0, the rest is
 * clamped to [0, 1], encoded (unless linear), and rounded to the nearest of 256 steps. */
int image_encode_8bit(double linear, PngEncoding encoding)
{
    double v = isnan(linear) ? 0.0 : fmin(fmax(linear, 0.0), 1.0);
    if (encoding == PNG_ENCODING_SRGB)
        v = image_srgb_encode(v);
    return (int)(v * 255 + 0.5);
}

/* Returns the linear value of an sRGB-encoded one: the inverse of image_srgb_encode. */
double image_srgb_decode(double encoded)
{
    if (encoded <= 0.04045)
        return encoded / 12.92;
    return pow((encoded + 0.055) / 1.055, 2.4);
}

/* Returns the format that path's extension names (.png, .pfm or .exr, in any case). */
ImageFormat image_format_for_path(const char *path)
{
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(slash ? slash + 1 : path, '.');
    if (dot == NULL)
        return IMAGE_FORMAT_UNKNOWN;
    if (strcasecmp(dot, ".png") == 0)
        return IMAGE_FORMAT_PNG;
    if (strcasecmp(dot, ".pfm") == 0)
        return IMAGE_FORMAT_PFM;
    if (strcasecmp(dot, ".exr") == 0)
        return IMAGE_FORMAT_EXR;
    return IMAGE_FORMAT_UNKNOWN;
}

/* Writes img to path in the format its extension names; the file appears only when
 * complete, and an existing file stays as it was when anything fails. */
bool image_write(const Image *img, const char *path, PngEncoding encoding, Error *err)
{
    ImageFormat format = image_format_for_path(path);
    if (img->pixels == NULL || !image_size_ok(img->width, img->height)) {
        error_set(err, "no image to write");
        return false;
    }
    if (format == IMAGE_FORMAT_UNKNOWN) {
        error_set(err, "unknown image format (use .png, .pfm or .exr)");
        return false;
    }
    OutFile out;
    if (!outfile_open(&out, path, err))
        return false;
    bool written = format == IMAGE_FORMAT_PNG   ? image_write_png(img, out.file, encoding, err)
                   : format == IMAGE_FORMAT_PFM ? image_write_pfm(img, out.file, err)
                                                : image_write_exr(img, out.file, err);
    if (!written) {
        outfile_abort(&out);
        return false;
    }
    return outfile_commit(&out, err);
}
