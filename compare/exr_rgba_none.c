/* exr_rgba_none.c: a build without OpenEXR's library (a student's starter): the OpenEXR files
 * raytra's own reader does not decode are refused, saying so. */
#include "exr_rgba.h"

/* Refuses the image at path: reading it needs OpenEXR's library, which this build lacks. */
bool exr_rgba_read(const char *path, Image *img, Error *err)
{
    (void)path;
    (void)img;
    error_set(err, "tiles, luminance and chroma, and compressions other than NONE, RLE, ZIPS and "
                   "ZIP need OpenEXR's library, which this build of the tools does without");
    return false;
}
