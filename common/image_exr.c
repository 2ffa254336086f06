/* image_exr.c: writing an image as OpenEXR: its R, G and B as 32-bit floats. */
#include "image.h"

#include <errno.h>
#include <string.h>

#include "exr.h"

/* Writes img to f as an OpenEXR image: linear 32-bit float R, G and B channels, lossless
 * ZIP compression, one part of scanlines. Floats, not halves: halves hold nothing above
 * 65504, and a float image is the PFM's values exactly. */
bool image_write_exr(const Image *img, FILE *f, Error *err)
{
    const ExrPlane planes[3] = {{"R", img->pixels, 3}, {"G", img->pixels + 1, 3},
                                {"B", img->pixels + 2, 3}};
    if (!exr_write(f, img->width, img->height, planes, 3, NULL, 0, err))
        return false;
    if (fflush(f) != 0) {
        error_set(err, "%s", strerror(errno));
        return false;
    }
    return true;
}
