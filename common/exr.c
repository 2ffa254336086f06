/* exr.c: writing OpenEXR files of one scanline part, 32-bit floats, ZIP-compressed, on zlib. */
#include "exr.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <zlib.h>

#include "stop.h"

/* Bytes on their way into a file: the header, or a chunk. */
typedef struct {
    unsigned char *data;
    size_t size, capacity;
    bool failed; /* out of memory */
} Bytes;

/* Appends n bytes to b. */
static void put(Bytes *b, const void *bytes, size_t n)
{
    if (b->failed)
        return;
    if (b->size + n > b->capacity) {
        size_t capacity = 2 * (b->size + n);
        unsigned char *data = realloc(b->data, capacity);
        if (data == NULL) {
            b->failed = true;
            return;
        }
        b->data = data;
        b->capacity = capacity;
    }
    memcpy(b->data + b->size, bytes, n);
    b->size += n;
}

/* Appends v as a little-endian integer of n bytes (the format's byte order throughout). */
static void put_le(Bytes *b, uint64_t v, int n)
{
    unsigned char le[8];
    for (int k = 0; k < n; k++)
        le[k] = (unsigned char)(v >> (8 * k));
    put(b, le, (size_t)n);
}

/* Appends an attribute's name, type and size; its value follows. */
static void put_attribute(Bytes *b, const char *name, const char *type, size_t size)
{
    put(b, name, strlen(name) + 1);
    put(b, type, strlen(type) + 1);
    put_le(b, size, 4);
}

/* Appends a box2i attribute: the pixels from (0, 0) to (width - 1, height - 1). */
static void put_window(Bytes *b, const char *name, int width, int height)
{
    put_attribute(b, name, "box2i", 16);
    put_le(b, 0, 4);
    put_le(b, 0, 4);
    put_le(b, (uint32_t)(width - 1), 4);
    put_le(b, (uint32_t)(height - 1), 4);
}

/* Appends the float v, little-endian. */
static void put_float(Bytes *b, float v)
{
    uint32_t bits;
    memcpy(&bits, &v, sizeof bits);
    put_le(b, bits, 4);
}

/* The header: the magic number, version 2 (single part, scanlines, short names), then
 * every attribute the format requires and the caller's, and a zero byte that ends them. */
static void put_header(Bytes *b, int width, int height, const ExrPlane *planes,
                       const int *order, int count, const ExrAttribute *attributes,
                       int attribute_count)
{
    put(b, EXR_MAGIC, 4);
    put_le(b, 2, 4);
    size_t list = 1;
    for (int c = 0; c < count; c++)
        list += strlen(planes[c].name) + 1 + 16;
    put_attribute(b, "channels", "chlist", list);
    for (int c = 0; c < count; c++) {
        /* Name, sample type, pLinear and three reserved bytes, x and y sampling. */
        put(b, planes[order[c]].name, strlen(planes[order[c]].name) + 1);
        put_le(b, EXR_FLOAT, 4);
        put_le(b, 0, 4);
        put_le(b, 1, 4);
        put_le(b, 1, 4);
    }
    put_le(b, 0, 1);
    put_attribute(b, "compression", "compression", 1);
    put_le(b, EXR_ZIP, 1);
    put_window(b, "dataWindow", width, height);
    put_window(b, "displayWindow", width, height);
    put_attribute(b, "lineOrder", "lineOrder", 1);
    put_le(b, 0, 1); /* increasing y */
    put_attribute(b, "pixelAspectRatio", "float", 4);
    put_float(b, 1);
    put_attribute(b, "screenWindowCenter", "v2f", 8);
    put_float(b, 0);
    put_float(b, 0);
    put_attribute(b, "screenWindowWidth", "float", 4);
    put_float(b, 1);
    for (int k = 0; k < attribute_count; k++) {
        const ExrAttribute *a = &attributes[k];
        if (a->text != NULL) {
            put_attribute(b, a->name, "string", strlen(a->text));
            put(b, a->text, strlen(a->text));
        } else {
            put_attribute(b, a->name, "int", 4);
            put_le(b, (uint32_t)a->value, 4);
        }
    }
    put_le(b, 0, 1);
}

/* Stores the bytes of lines y0 to y1 - 1 in raw as the format lays them out: each line,
 * each channel in turn (in the order of the header), its floats little-endian; returns
 * how many. */
static size_t pack_lines(const ExrPlane *planes, const int *order, int count, int width, int y0,
                         int y1, unsigned char *raw)
{
    unsigned char *at = raw;
    for (int y = y0; y < y1; y++)
        for (int c = 0; c < count; c++) {
            const ExrPlane *p = &planes[order[c]];
            const float *row = p->first + (long)y * width * p->step;
            for (int x = 0; x < width; x++, at += 4) {
                uint32_t bits;
                memcpy(&bits, &row[(long)x * p->step], sizeof bits);
                at[0] = (unsigned char)bits;
                at[1] = (unsigned char)(bits >> 8);
                at[2] = (unsigned char)(bits >> 16);
                at[3] = (unsigned char)(bits >> 24);
            }
        }
    return (size_t)(at - raw);
}

/* ZIP's preparation of the bytes before deflate: the even bytes, then the odd ones (the
 * low and high bytes of the values apart), each byte then replaced by its difference
 * from the one before, plus 128. */
static void zip_prepare(const unsigned char *raw, size_t n, unsigned char *out)
{
    size_t half = (n + 1) / 2;
    for (size_t k = 0; k < half; k++)
        out[k] = raw[2 * k];
    for (size_t k = 0; k < n / 2; k++)
        out[half + k] = raw[2 * k + 1];
    for (size_t k = n - 1; k > 0; k--)
        out[k] = (unsigned char)(out[k] - out[k - 1] + 128);
}

/* Writes n bytes at the stream's position; false (in err) on failure. */
static bool write_all(FILE *f, const void *bytes, size_t n, Error *err)
{
    if (fwrite(bytes, 1, n, f) == n)
        return true;
    error_set(err, "%s", strerror(errno));
    return false;
}

/* Writes the chunks of 16 lines one after the other, each its first line, its size and its
 * bytes (deflated, or as they are when deflate would not make them smaller), and their
 * offsets into table; false (in err) on failure or a stop request. */
static bool write_chunks(FILE *f, int width, int height, const ExrPlane *planes,
                         const int *order, int count, uint64_t *table, Error *err)
{
    Bytes chunk = {0};
    size_t most = (size_t)count * 4 * (size_t)width * 16;
    unsigned char *raw = malloc(most), *prepared = malloc(most);
    uLongf bound = compressBound((uLong)most);
    unsigned char *deflated = malloc(bound);
    bool ok = raw != NULL && prepared != NULL && deflated != NULL;
    if (!ok)
        error_set(err, "out of memory");
    for (int y = 0, k = 0; ok && y < height; y += 16, k++) {
        /* A stop request ends the writing between chunks: the temporary is then removed. */
        if (stop_requested()) {
            error_set(err, "interrupted");
            ok = false;
            break;
        }
        size_t n = pack_lines(planes, order, count, width, y, y + 16 < height ? y + 16 : height, raw);
        zip_prepare(raw, n, prepared);
        uLongf size = bound;
        const unsigned char *data = deflated;
        if (compress(deflated, &size, prepared, (uLong)n) != Z_OK || size >= n) {
            data = raw;
            size = (uLongf)n;
        }
        off_t at = ftello(f);
        table[k] = (uint64_t)at;
        chunk.size = 0;
        put_le(&chunk, (uint32_t)y, 4);
        put_le(&chunk, size, 4);
        ok = at >= 0 && !chunk.failed && write_all(f, chunk.data, chunk.size, err) &&
             write_all(f, data, size, err);
        if (at < 0)
            error_set(err, "%s", strerror(errno));
    }
    free(raw);
    free(chunk.data);
    free(prepared);
    free(deflated);
    return ok;
}

/* Writes a width x height OpenEXR image of the given channels (32-bit floats, each plane's
 * name at most 31 bytes) and attributes to f, which must be a file that can seek: one
 * scanline part, lossless ZIP compression in chunks of 16 lines, increasing y; the header
 * lists the channels by name, as the format wants. False (in err) on failure or a stop
 * request; f then holds part of a file. */
bool exr_write(FILE *f, int width, int height, const ExrPlane *planes, int plane_count,
               const ExrAttribute *attributes, int attribute_count, Error *err)
{
    /* The channels' order in the header and in each line: by name. */
    int order[64];
    if (plane_count < 1 || plane_count > 64) {
        error_set(err, "%d channels", plane_count);
        return false;
    }
    for (int c = 0; c < plane_count; c++) {
        int at = c;
        for (; at > 0 && strcmp(planes[order[at - 1]].name, planes[c].name) > 0; at--)
            order[at] = order[at - 1];
        order[at] = c;
    }
    Bytes header = {0};
    put_header(&header, width, height, planes, order, plane_count, attributes, attribute_count);
    /* The offset table follows the header: zeros until the chunks' offsets are known. */
    size_t chunks = (size_t)(height + 15) / 16;
    uint64_t *table = calloc(chunks, sizeof *table);
    Bytes le = {0};
    bool ok = !header.failed && table != NULL;
    if (!ok)
        error_set(err, "out of memory");
    off_t start = ok ? ftello(f) : -1;
    ok = ok && write_all(f, header.data, header.size, err);
    for (size_t k = 0; ok && k < chunks; k++)
        ok = write_all(f, &table[k], sizeof table[k], err);
    ok = ok && write_chunks(f, width, height, planes, order, plane_count, table, err);
    for (size_t k = 0; ok && k < chunks; k++)
        put_le(&le, table[k], 8);
    if (ok && le.failed) {
        error_set(err, "out of memory");
        ok = false;
    }
    if (ok && fseeko(f, start + (off_t)header.size, SEEK_SET) != 0) {
        error_set(err, "%s", strerror(errno));
        ok = false;
    }
    ok = ok && write_all(f, le.data, le.size, err);
    if (ok && fseeko(f, 0, SEEK_END) != 0) {
        error_set(err, "%s", strerror(errno));
        ok = false;
    }
    free(header.data);
    free(le.data);
    free(table);
    return ok;
}
