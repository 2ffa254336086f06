/* imgfile.c: what a file holds, told from its first bytes and header without decoding it. */
#include "imgfile.h"

#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "image.h"

/* The largest header read: a PNG's IHDR is at byte 16, an EXR's dataWindow within it. */
#define HEADER_BYTES 4096

/* Returns what a file that is not a regular one is, in words: "a FIFO". */
const char *imgfile_kind_text(mode_t mode)
{
    return S_ISLNK(mode)    ? "a symbolic link"
           : S_ISFIFO(mode) ? "a FIFO"
           : S_ISDIR(mode)  ? "a folder"
                            : "a special file";
}

/* Opens path for reading only when it is a regular file, never blocking on a FIFO or a
 * device and never following a symbolic link: a student's file may be any of these.
 * Returns the descriptor, or -1 (err) when it is not a readable regular file. */
static int imgfile_open(const char *path, Error *err)
{
    struct stat st;
    if (lstat(path, &st) != 0) {
        error_set(err, "%s", strerror(errno));
        return -1;
    }
    if (S_ISLNK(st.st_mode) || !S_ISREG(st.st_mode)) {
        error_set(err, "not a regular file (%s)", imgfile_kind_text(st.st_mode));
        return -1;
    }
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOFOLLOW | O_CLOEXEC);
    /* Checked again on the descriptor: the path may have changed since lstat. */
    if (fd >= 0 && (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode))) {
        close(fd);
        error_set(err, "not a regular file");
        return -1;
    }
    if (fd < 0)
        error_set(err, "%s", strerror(errno));
    return fd;
}

/* Opens path for reading as imgfile_open does, as a stream; NULL when it cannot. */
FILE *imgfile_fopen(const char *path)
{
    Error err;
    int fd = imgfile_open(path, &err);
    FILE *f = fd >= 0 ? fdopen(fd, "rb") : NULL;
    if (fd >= 0 && f == NULL)
        close(fd);
    return f;
}

/* Returns the big-endian 32-bit number at p (PNG). */
static uint32_t big32(const unsigned char *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

/* Returns the little-endian 32-bit number at p (EXR). */
static int32_t little32(const unsigned char *p)
{
    return (int32_t)((uint32_t)p[3] << 24 | (uint32_t)p[2] << 16 | (uint32_t)p[1] << 8 | p[0]);
}

/* Finds an EXR's size in its header: after the magic and version come attributes, each
 * NAME\0 TYPE\0 SIZE VALUE, until an empty name; dataWindow is a box2i (xmin, ymin, xmax,
 * ymax). False when the header in h[0..n) holds none. */
static bool exr_size(const unsigned char *h, size_t n, long *width, long *height)
{
    size_t p = 8;
    while (p < n && h[p] != '\0') {
        const char *name = (const char *)h + p;
        size_t name_len = strnlen(name, n - p);
        size_t type = p + name_len + 1;
        size_t type_len = type < n ? strnlen((const char *)h + type, n - type) : n;
        size_t value = type + type_len + 5;
        if (value > n)
            return false;
        int32_t size = little32(h + value - 4);
        if (size < 0 || (size_t)size > n - value)
            return false;
        if (strcmp(name, "dataWindow") == 0 && size == 16) {
            *width = (long)little32(h + value + 8) - little32(h + value) + 1;
            *height = (long)little32(h + value + 12) - little32(h + value + 4) + 1;
            return true;
        }
        p = value + (size_t)size;
    }
    return false;
}

/* Reads the format and size of the image at path from its header alone, so that sizes are
 * compared, and huge images refused, before anything is decoded: a 0.5 MB PNG may hold
 * 8192 x 8192 pixels. False (err) when the file is not a PNG, PFM or EXR image. */
bool imgfile_header(const char *path, ImgFileKind *kind, int *width, int *height, Error *err)
{
    static const unsigned char png_magic[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    static const unsigned char exr_magic[4] = {0x76, 0x2F, 0x31, 0x01};
    unsigned char h[HEADER_BYTES + 1];
    int fd = imgfile_open(path, err);
    if (fd < 0)
        return false;
    ssize_t got = read(fd, h, HEADER_BYTES);
    close(fd);
    size_t n = got > 0 ? (size_t)got : 0;
    h[n] = '\0';
    long w = 0, ht = 0;
    *kind = IMGFILE_UNKNOWN;
    if (n >= 24 && memcmp(h, png_magic, 8) == 0 && memcmp(h + 12, "IHDR", 4) == 0) {
        *kind = IMGFILE_PNG;
        w = (long)big32(h + 16);
        ht = (long)big32(h + 20);
    } else if (n >= 2 && h[0] == 'P' && (h[1] == 'F' || h[1] == 'f')) {
        *kind = IMGFILE_PFM;
        if (sscanf((const char *)h + 2, "%ld %ld", &w, &ht) != 2)
            w = ht = 0;
    } else if (n >= 8 && memcmp(h, exr_magic, 4) == 0) {
        *kind = IMGFILE_EXR;
        if (!exr_size(h, n, &w, &ht))
            w = ht = 0;
    }
    if (*kind == IMGFILE_UNKNOWN) {
        error_set(err, n == 0 ? "empty file" : "not a PNG, PFM or OpenEXR image");
        return false;
    }
    if (!image_size_ok(w, ht)) {
        error_set(err,
                  "its header gives a size of %ld x %ld pixels, beyond the %d x %d (and "
                  "%ld pixels) imgdiff reads",
                  w, ht, IMAGE_MAX_SIDE, IMAGE_MAX_SIDE, IMAGE_MAX_PIXELS);
        return false;
    }
    *width = (int)w;
    *height = (int)ht;
    return true;
}
