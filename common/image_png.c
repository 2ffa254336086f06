/* image_png.c: writing and reading PNG through libpng, its errors turned into messages. */
#include "image.h"

#include <errno.h>
#include <math.h>
#include <png.h>
#include <stdlib.h>
#include <string.h>

#include "stop.h"

/* No chunk besides the pixels (text, an ICC profile) may make libpng allocate more. */
#define CHUNK_MEMORY_MAX (8L << 20)

/* What reading a PNG allocates, kept outside the function that calls setjmp: after
 * a longjmp, that function's own changed variables would have unknown values. */
typedef struct {
    png_structp png;
    png_infop info;
    png_bytep rows; /* decoded bytes: one row, or all of them for an interlaced image */
} Reader;

/* libpng's error handler: keeps the message for the caller and jumps back to setjmp. */
static void on_error(png_structp png, png_const_charp message)
{
    error_set(png_get_error_ptr(png), "%s", message);
    png_longjmp(png, 1);
}

/* libpng's warning handler: warnings (an odd ancillary chunk) leave the pixels alone. */
static void on_warning(png_structp png, png_const_charp message)
{
    (void)png;
    (void)message;
}

/* libpng's write function: stdio, with a failed write made a libpng error. */
static void write_bytes(png_structp png, png_bytep data, size_t length)
{
    if (fwrite(data, 1, length, png_get_io_ptr(png)) != length)
        png_error(png, strerror(errno));
}

/* libpng's flush function: nothing to do, as the file's owner flushes it when done. */
static void flush_bytes(png_structp png)
{
    (void)png;
}

/* libpng's read function: stdio, with a file that ends early reported as truncated. */
static void read_bytes(png_structp png, png_bytep data, size_t length)
{
    FILE *f = png_get_io_ptr(png);
    if (fread(data, 1, length, f) != length)
        png_error(png, ferror(f) ? strerror(errno) : "truncated");
}


/* Writes img as 8-bit RGB; false (in the error handler's message) when libpng fails. */
static bool write_png(png_structp png, png_infop info, const Image *img, PngEncoding encoding,
                      png_bytep row)
{
    if (setjmp(png_jmpbuf(png)))
        return false;
    png_set_IHDR(png, info, (png_uint_32)img->width, (png_uint_32)img->height, 8,
                 PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    /* How to read the values; no time stamp, so that equal images make equal files. */
    if (encoding == PNG_ENCODING_SRGB)
        png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    else
        png_set_gAMA(png, info, 1.0);
    png_write_info(png, info);
    for (int y = 0; y < img->height; y++) {
        /* A stop request ends the writing at once; the caller removes the temporary. */
        if (stop_requested())
            png_error(png, "interrupted");
        const float *p = img->pixels + 3L * y * img->width;
        for (long k = 0; k < 3L * img->width; k++)
            row[k] = (png_byte)image_encode_8bit(p[k], encoding);
        png_write_row(png, row);
    }
    png_write_end(png, NULL);
    return true;
}

/* Writes img to f as an 8-bit RGB PNG, the values encoded as encoding says. */
bool image_write_png(const Image *img, FILE *f, PngEncoding encoding, Error *err)
{
    png_bytep row = malloc(3 * (size_t)img->width);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, err, on_error, on_warning);
    png_infop info = png != NULL ? png_create_info_struct(png) : NULL;
    bool ok = false;
    if (row == NULL || info == NULL) {
        error_set(err, "out of memory");
    } else {
        png_set_write_fn(png, f, write_bytes, flush_bytes);
        ok = write_png(png, info, img, encoding, row);
    }
    png_destroy_write_struct(&png, &info);
    free(row);
    return ok;
}

/* Returns the big-endian 32-bit number at p, as PNG stores them. */
static unsigned long get_be32(const unsigned char *p)
{
    return (unsigned long)p[0] << 24 | (unsigned long)p[1] << 16 | (unsigned long)p[2] << 8 | p[3];
}

/* Checks the signature and, before libpng allocates anything, the size in the IHDR
 * chunk that must follow it; then rewinds f for libpng. */
static bool check_start(FILE *f, Error *err)
{
    /* Signature (8 bytes), IHDR's length and type (8), width and height (8). */
    unsigned char start[24];
    size_t n = fread(start, 1, sizeof start, f);
    if (ferror(f)) {
        error_set(err, "%s", strerror(errno));
        return false;
    }
    if (n == 0 || png_sig_cmp(start, 0, n < 8 ? n : 8) != 0) {
        error_set(err, "not a PNG file");
        return false;
    }
    if (n < sizeof start) {
        error_set(err, "truncated");
        return false;
    }
    unsigned long width = get_be32(start + 16), height = get_be32(start + 20);
    long too_big = IMAGE_MAX_SIDE + 1L;
    if (memcmp(start + 12, "IHDR", 4) == 0 &&
        !image_size_ok(width < (unsigned long)too_big ? (long)width : too_big,
                       height < (unsigned long)too_big ? (long)height : too_big)) {
        error_set(err,
                  "the image is %lu x %lu pixels: outside the limits (1 to %d a side, "
                  "at most %ld pixels)",
                  width, height, IMAGE_MAX_SIDE, IMAGE_MAX_PIXELS);
        return false;
    }
    if (fseek(f, 0, SEEK_SET) != 0) {
        error_set(err, "%s", strerror(errno));
        return false;
    }
    return true;
}

/* Stores one decoded row (RGB or RGBA, 1 or 2 bytes a sample, big-endian) as row y of
 * img: each value divided by its maximum, the colour multiplied by alpha (over black). */
static void store_row(Image *img, int y, png_const_bytep row, int channels, int bytes)
{
    double max = bytes == 2 ? 65535.0 : 255.0;
    float *out = img->pixels + 3L * y * img->width;
    for (int x = 0; x < img->width; x++) {
        double v[4] = {0, 0, 0, max};
        for (int c = 0; c < channels; c++) {
            png_const_bytep s = row + ((size_t)x * channels + c) * bytes;
            v[c] = bytes == 2 ? (s[0] << 8 | s[1]) : s[0];
        }
        double alpha = v[3] / max;
        for (int c = 0; c < 3; c++)
            out[3 * x + c] = (float)(v[c] / max * alpha);
    }
}

/* Decodes the PNG that r's libpng reads into img; false (in the error handler's
 * message) when libpng fails. */
static bool read_png(Reader *r, Image *img)
{
    png_structp png = r->png;
    if (setjmp(png_jmpbuf(png)))
        return false;
    png_set_user_limits(png, IMAGE_MAX_SIDE, IMAGE_MAX_SIDE);
    png_set_chunk_malloc_max(png, CHUNK_MEMORY_MAX);
    png_read_info(png, r->info);
    /* Palette to RGB, gray below 8 bits to 8 bits, tRNS to an alpha channel; then gray
     * to RGB. 16-bit samples stay 16-bit, in PNG's byte order, which store_row reads. */
    png_set_expand(png);
    png_set_gray_to_rgb(png);
    int passes = png_set_interlace_handling(png);
    png_read_update_info(png, r->info);
    int width = (int)png_get_image_width(png, r->info);
    int height = (int)png_get_image_height(png, r->info);
    int channels = png_get_channels(png, r->info);
    int bytes = png_get_bit_depth(png, r->info) / 8;
    size_t stride = png_get_rowbytes(png, r->info);
    /* An interlaced image comes in passes, each filling in some pixels of every row. */
    r->rows = calloc(passes > 1 ? (size_t)height : 1, stride);
    if (r->rows == NULL || !image_init(img, width, height))
        png_error(png, "out of memory");
    for (int pass = 0; pass < passes; pass++)
        for (int y = 0; y < height; y++) {
            png_bytep row = r->rows + (passes > 1 ? (size_t)y * stride : 0);
            png_read_row(png, row, NULL);
            if (pass == passes - 1)
                store_row(img, y, row, channels, bytes);
        }
    png_read_end(png, NULL);
    return true;
}

/* Reads the PNG at path into img (overwritten; left empty on failure), as stored. */
bool image_read_png(Image *img, const char *path, Error *err)
{
    /* The values are the file's own, stored value / 255 (or / 65535), not linearised:
     * images are compared on the values their files hold. Alpha composites over black. */
    *img = (Image){0};
    FILE *f = fopen(path, "rb");
    if (f == NULL) {
        error_set(err, "%s", strerror(errno));
        return false;
    }
    bool ok = false;
    if (check_start(f, err)) {
        Reader r = {0};
        r.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, err, on_error, on_warning);
        r.info = r.png != NULL ? png_create_info_struct(r.png) : NULL;
        if (r.info == NULL) {
            error_set(err, "out of memory");
        } else {
            png_set_read_fn(r.png, f, read_bytes);
            ok = read_png(&r, img);
        }
        png_destroy_read_struct(&r.png, &r.info, NULL);
        free(r.rows);
    }
    fclose(f);
    if (!ok)
        image_free(img);
    return ok;
}
