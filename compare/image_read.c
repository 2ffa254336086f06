/* image_read.c: reading an image, PNG, PFM or OpenEXR, as its first bytes tell. */
#include "image_read.h"

#include <errno.h>
#include <string.h>

#include "exr.h"

/* The eight bytes every PNG file starts with. */
static const unsigned char magic_png[8] = {137, 'P', 'N', 'G', '\r', '\n', 26, '\n'};

/* Reads the image at path, PNG, PFM or OpenEXR as its first bytes tell (not its name), into img,
 * which is overwritten; on failure img is left empty. */
bool image_read(Image *img, const char *path, Error *err)
{
    *img = (Image){0};
    FILE *f = fopen(path, "rb");
    if (f == NULL) {
        error_set(err, "%s", strerror(errno));
        return false;
    }
    unsigned char magic[8];
    size_t n = fread(magic, 1, sizeof magic, f);
    int read_errno = errno;
    bool failed = ferror(f);
    fclose(f);
    if (failed) {
        error_set(err, "%s", strerror(read_errno));
        return false;
    }
    if (n == sizeof magic && memcmp(magic, magic_png, sizeof magic) == 0)
        return image_read_png(img, path, err);
    if (n >= 2 && magic[0] == 'P' && (magic[1] == 'F' || magic[1] == 'f'))
        return image_read_pfm(img, path, err);
    if (n >= 4 && memcmp(magic, EXR_MAGIC, 4) == 0)
        return image_read_exr(img, path, err);
    error_set(err, n == 0 ? "empty file" : "not a PNG, PFM or OpenEXR image");
    return false;
}
