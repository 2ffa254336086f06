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
#include "image_read.h"

/* The first bytes read: a PNG's IHDR is at byte 16, a PFM's size within them. An EXR's
 * header, of any length, is parsed by the OpenEXR library. */
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
        /* The library parses the header, and checks its size and channels. */
        *kind = IMGFILE_EXR;
        FILE *f = fdopen(fd, "rb");
        if (f == NULL) {
            error_set(err, "%s", strerror(errno));
            close(fd);
            return false;
        }
        bool ok = image_exr_size(f, width, height, err);
        fclose(f);
        return ok;
    }
    close(fd);
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

/* Returns the encoding that writes an image read from a file of kind `kind` back to a PNG as
 * it looks: a PNG's values as they were read, linear ones as raytra encodes its PNGs. */
PngEncoding imgfile_encoding(ImgFileKind kind)
{
    return kind == IMGFILE_PNG ? PNG_ENCODING_LINEAR : PNG_ENCODING_SRGB;
}
