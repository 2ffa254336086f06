/* image_pfm.c: reading and writing PFM, the lossless float image format. */
#include "image.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "stop.h"

/* A PFM sample is an IEEE 754 single, copied bit for bit to and from 32-bit integers. */
_Static_assert(sizeof(float) == sizeof(uint32_t), "float must be 32 bits");

/* The longest header word (a size or the scale) that is read. */
#define WORD_MAX 31

/* Stores the bits of v at p, least significant byte first, whatever the machine's order. */
static void put_le32(unsigned char *p, float v)
{
    uint32_t bits;
    memcpy(&bits, &v, sizeof bits);
    for (int k = 0; k < 4; k++)
        p[k] = (unsigned char)(bits >> 8 * k);
}

/* Returns the float whose bits are at p, in little- or big-endian byte order. */
static float get_float(const unsigned char *p, bool little_endian)
{
    uint32_t bits = 0;
    for (int k = 0; k < 4; k++)
        bits = bits << 8 | p[little_endian ? 3 - k : k];
    float v;
    memcpy(&v, &bits, sizeof v);
    return v;
}

/* Writes img to f as PFM: a text header, then little-endian floats (the negative scale
 * says so), the rows from the bottom up as PFM has them. */
bool image_write_pfm(const Image *img, FILE *f, Error *err)
{
    size_t row_bytes = 12 * (size_t)img->width;
    unsigned char *row = malloc(row_bytes);
    if (row == NULL) {
        error_set(err, "out of memory");
        return false;
    }
    bool ok = fprintf(f, "PF\n%d %d\n-1.0\n", img->width, img->height) > 0;
    bool stopped = false;
    for (int y = img->height - 1; ok && y >= 0; y--) {
        /* A stop request ends the writing at once; the caller removes the temporary. */
        if (stop_requested()) {
            stopped = true;
            ok = false;
            break;
        }
        const float *p = img->pixels + 3L * y * img->width;
        for (long k = 0; k < 3L * img->width; k++)
            put_le32(row + 4 * k, p[k]);
        ok = fwrite(row, 1, row_bytes, f) == row_bytes;
    }
    if (stopped)
        error_set(err, "interrupted");
    else if (!ok)
        error_set(err, "%s", strerror(errno));
    free(row);
    return ok;
}

/* Reads the next header word, skipping whitespace before it and consuming the one
 * whitespace character after it; false (reported) when the file ends or it is too long. */
static bool read_word(FILE *f, const char *what, char word[WORD_MAX + 1], Error *err)
{
    int c;
    while ((c = getc(f)) != EOF && isspace(c))
        ;
    int n = 0;
    while (c != EOF && !isspace(c)) {
        if (n == WORD_MAX) {
            word[n] = '\0';
            error_set(err, "bad PFM header: the %s '%s...' is too long", what, word);
            return false;
        }
        word[n++] = (char)c;
        c = getc(f);
    }
    word[n] = '\0';
    if (c == EOF) {
        error_set(err,
                  n == 0 ? "bad PFM header: the file ends before the %s"
                         : "bad PFM header: the file ends within the %s",
                  what);
        return false;
    }
    return true;
}

/* Reads a size into word and *size; false (reported) unless it is all digits. */
static bool read_size(FILE *f, const char *what, char word[WORD_MAX + 1], long *size, Error *err)
{
    if (!read_word(f, what, word, err))
        return false;
    size_t digits = strspn(word, "0123456789");
    if (digits == 0 || word[digits] != '\0') {
        error_set(err, "bad PFM header: the %s '%s' is not a whole number", what, word);
        return false;
    }
    /* Too many digits give LONG_MAX, which the size check then refuses. */
    *size = strtol(word, NULL, 10);
    return true;
}

/* Reads the header after the magic: sizes and scale; false (reported) when malformed. */
static bool read_header(FILE *f, long *width, long *height, double *scale, Error *err)
{
    char word[WORD_MAX + 1], height_word[WORD_MAX + 1];
    if (!read_size(f, "width", word, width, err) ||
        !read_size(f, "height", height_word, height, err))
        return false;
    if (!image_size_ok(*width, *height)) {
        error_set(err,
                  "the image is %s x %s pixels: outside the limits (1 to %d a side, "
                  "at most %ld pixels)",
                  word, height_word, IMAGE_MAX_SIDE, IMAGE_MAX_PIXELS);
        return false;
    }
    /* The scale's sign gives the byte order; the one character after it ends the header. */
    if (!read_word(f, "scale", word, err))
        return false;
    char *end;
    *scale = strtod(word, &end);
    if (*end != '\0' || !isfinite(*scale) || *scale == 0) {
        error_set(err, "bad PFM header: the scale '%s' is not a finite nonzero number", word);
        return false;
    }
    return true;
}

/* Reads the pixels, bottom row first, into img; false (reported) when the file is short. */
static bool read_pixels(FILE *f, Image *img, int channels, bool little_endian, Error *err)
{
    size_t row_bytes = 4 * (size_t)channels * (size_t)img->width;
    unsigned char *row = malloc(row_bytes);
    if (row == NULL) {
        error_set(err, "out of memory");
        return false;
    }
    size_t total = 0;
    bool ok = true;
    for (int y = img->height - 1; ok && y >= 0; y--) {
        size_t n = fread(row, 1, row_bytes, f);
        total += n;
        ok = n == row_bytes;
        float *out = img->pixels + 3L * y * img->width;
        for (long k = 0; ok && k < 3L * img->width; k++)
            out[k] = get_float(row + 4 * (channels == 3 ? k : k / 3), little_endian);
    }
    if (!ok && ferror(f))
        error_set(err, "%s", strerror(errno));
    else if (!ok)
        error_set(err, "truncated: expected %zu bytes of pixels, found %zu",
                  row_bytes * (size_t)img->height, total);
    free(row);
    return ok;
}

/* Reads a whole PFM from f into img; false (reported) when it is not a valid PFM. */
static bool read_pfm(FILE *f, Image *img, Error *err)
{
    char magic[3];
    if (fread(magic, 1, sizeof magic, f) != sizeof magic || magic[0] != 'P' ||
        (magic[1] != 'F' && magic[1] != 'f') || !isspace((unsigned char)magic[2])) {
        error_set(err, "%s",
                  ferror(f) ? strerror(errno) : "not a PFM file (it must start with PF or Pf)");
        return false;
    }
    long width, height;
    double scale;
    if (!read_header(f, &width, &height, &scale, err))
        return false;
    if (!image_init(img, (int)width, (int)height)) {
        error_set(err, "out of memory for a %ld x %ld image", width, height);
        return false;
    }
    return read_pixels(f, img, magic[1] == 'F' ? 3 : 1, scale < 0, err);
}

/* Reads the PFM at path into img (overwritten; left empty on failure), gray ("Pf") too. */
bool image_read_pfm(Image *img, const char *path, Error *err)
{
    /* The scale's size is not applied: writers put 1 there, and the values are read as
     * they are. Bytes after the pixels are ignored. */
    *img = (Image){0};
    FILE *f = fopen(path, "rb");
    if (f == NULL) {
        error_set(err, "%s", strerror(errno));
        return false;
    }
    bool ok = read_pfm(f, img, err);
    fclose(f);
    if (!ok)
        image_free(img);
    return ok;
}
