/* exr_rgba.c: reading an OpenEXR image through OpenEXR's C interface to RGBA files
 * (ImfCRgbaFile.h, the same in OpenEXR 2 and 3): every layout and compression, as halves. */
#include "exr_rgba.h"

#include <ImfCRgbaFile.h>
#include <stdlib.h>

/* Lines read at a time: the halves of a strip, not of the whole image, are held. */
#define STRIP 64

/* Reads the image at path into img, already of the size of its data window: R, G and B
 * as OpenEXR's RgbaInputFile gives them (luminance and chroma converted, Y alone as grey,
 * every value rounded to a half); false (in err) when the library cannot. */
bool exr_rgba_read(const char *path, Image *img, Error *err)
{
    ImfInputFile *in = ImfOpenInputFile(path);
    if (in == NULL) {
        error_set(err, "%s", ImfErrorMessage());
        return false;
    }
    int x0, y0, x1, y1;
    ImfHeaderDataWindow(ImfInputHeader(in), &x0, &y0, &x1, &y1);
    long width = (long)x1 - x0 + 1, height = (long)y1 - y0 + 1;
    ImfRgba *strip = malloc(sizeof *strip * (size_t)width * STRIP);
    bool ok = strip != NULL && width == img->width && height == img->height;
    if (!ok)
        error_set(err, strip == NULL ? "out of memory" : "OpenEXR reads another size");
    for (long y = 0; ok && y < height; y += STRIP) {
        long lines = height - y < STRIP ? height - y : STRIP;
        /* The library finds pixel (x, y) at base + x + y * width. */
        ImfRgba *base = strip - x0 - (y0 + y) * width;
        ok = ImfInputSetFrameBuffer(in, base, 1, (size_t)width) != 0 &&
             ImfInputReadPixels(in, y0 + (int)y, y0 + (int)(y + lines - 1)) != 0;
        if (!ok) {
            error_set(err, "%s", ImfErrorMessage());
            break;
        }
        float *out = img->pixels + 3 * y * width;
        for (long k = 0; k < lines * width; k++) {
            out[3 * k] = ImfHalfToFloat(strip[k].r);
            out[3 * k + 1] = ImfHalfToFloat(strip[k].g);
            out[3 * k + 2] = ImfHalfToFloat(strip[k].b);
        }
    }
    free(strip);
    if (!ImfCloseInputFile(in) && ok) {
        error_set(err, "%s", ImfErrorMessage());
        ok = false;
    }
    return ok;
}
