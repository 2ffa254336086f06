/* exr_read.c: reading OpenEXR headers, and the pixels of scanline files compressed with NONE,
 * RLE, ZIPS or ZIP (what zlib undoes), every byte checked against what the header says. */
#include "exr_read.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <zlib.h>

/* The limits of what is read: no header, channel list or chunk asks for more memory. */
#define MAX_HEADER_BYTES (16L << 20)
#define MAX_CHANNELS 1024
#define MAX_CHUNK_BYTES (256L << 20)

/* Lines a chunk holds under each compression from NONE to DWAB. */
static const int lines_per_chunk[10] = {1, 1, 1, 16, 32, 16, 32, 32, 32, 256};

/* Returns the little-endian 32-bit integer at p. */
uint32_t exr_le32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* Returns the value of the half (IEEE 754 binary16) with bits h. */
float exr_half_to_float(uint16_t h)
{
    uint32_t sign = (uint32_t)(h & 0x8000) << 16, exponent = (h >> 10) & 0x1f, mantissa = h & 0x3ff;
    if (exponent == 0) {
        /* Zero or subnormal: mantissa x 2^-24, exact in a float. */
        float v = (float)mantissa * 0x1p-24f;
        return sign ? -v : v;
    }
    /* Normal (exponent rebiased from 15 to 127), or infinity and NaN. */
    uint32_t bits = sign | (exponent == 31 ? 0x7f800000u : (exponent + 112) << 23) | mantissa << 13;
    float v;
    memcpy(&v, &bits, sizeof v);
    return v;
}

/* Reads n bytes; false (in err) when the file ends first. */
static bool read_exactly(FILE *f, void *bytes, size_t n, Error *err)
{
    if (fread(bytes, 1, n, f) == n)
        return true;
    error_set(err, "%s", ferror(f) ? strerror(errno) : "the file ends in its header");
    return false;
}

/* Reads a zero-terminated name of at most 255 bytes into name (an empty one ends a list);
 * false (in err) otherwise. */
static bool read_name(FILE *f, char name[256], Error *err)
{
    for (int k = 0; k < 256; k++) {
        int c = getc(f);
        if (c == EOF) {
            error_set(err, "the file ends in its header");
            return false;
        }
        name[k] = (char)c;
        if (c == '\0')
            return true;
    }
    error_set(err, "a name in its header is longer than 255 bytes");
    return false;
}

/* Reads one header's attributes, up to the empty name that ends them, into h->attributes
 * (kept when keep); false (in err) when broken or too large. */
static bool read_attributes(FILE *f, ExrHeader *h, bool keep, Error *err)
{
    size_t used = 0;
    for (;;) {
        char name[256], type[256];
        unsigned char size_le[4];
        if (!read_name(f, name, err))
            return false;
        if (name[0] == '\0')
            break;
        if (!read_name(f, type, err) || !read_exactly(f, size_le, 4, err))
            return false;
        uint32_t size = exr_le32(size_le);
        size_t n = strlen(name) + strlen(type) + 2 + 4 + size;
        if (size > MAX_HEADER_BYTES || used + n > MAX_HEADER_BYTES) {
            error_set(err, "its header is larger than %ld bytes", MAX_HEADER_BYTES);
            return false;
        }
        if (!keep) {
            if (fseeko(f, size, SEEK_CUR) != 0) {
                error_set(err, "%s", strerror(errno));
                return false;
            }
            continue;
        }
        unsigned char *grown = realloc(h->attributes, used + n);
        if (grown == NULL) {
            error_set(err, "out of memory");
            return false;
        }
        h->attributes = grown;
        unsigned char *at = grown + used;
        memcpy(at, name, strlen(name) + 1);
        at += strlen(name) + 1;
        memcpy(at, type, strlen(type) + 1);
        at += strlen(type) + 1;
        memcpy(at, size_le, 4);
        if (!read_exactly(f, at + 4, size, err))
            return false;
        used += n;
        h->attributes_size = used;
    }
    return true;
}

/* Finds the attribute called name of the given type; its value (size bytes), or NULL. */
const unsigned char *exr_attribute(const ExrHeader *h, const char *name, const char *type,
                                   uint32_t *size)
{
    if (h->attributes == NULL)
        return NULL;
    const unsigned char *at = h->attributes, *end = at + h->attributes_size;
    while (at < end) {
        const char *n = (const char *)at, *t = n + strlen(n) + 1;
        const unsigned char *value = (const unsigned char *)t + strlen(t) + 1 + 4;
        uint32_t bytes = exr_le32(value - 4);
        if (strcmp(n, name) == 0 && strcmp(t, type) == 0) {
            *size = bytes;
            return value;
        }
        at = value + bytes;
    }
    return NULL;
}

/* Reads the int attribute called name into *value; false when there is none. */
bool exr_attribute_int(const ExrHeader *h, const char *name, int32_t *value)
{
    uint32_t size;
    const unsigned char *v = exr_attribute(h, name, "int", &size);
    if (v == NULL || size != 4)
        return false;
    *value = (int32_t)exr_le32(v);
    return true;
}

/* Reads the channel list (a chlist attribute's size bytes at list) into h; false (in err)
 * when it is broken. */
static bool read_channels(const unsigned char *list, uint32_t size, ExrHeader *h, Error *err)
{
    h->channels = calloc(MAX_CHANNELS, sizeof *h->channels);
    if (h->channels == NULL) {
        error_set(err, "out of memory");
        return false;
    }
    uint32_t at = 0;
    while (at < size && list[at] != '\0') {
        const unsigned char *end = memchr(list + at, '\0', size - at);
        size_t length = end != NULL ? (size_t)(end - (list + at)) : 0;
        if (end == NULL || length > 255 || size - at - length - 1 < 16 ||
            h->channel_count == MAX_CHANNELS) {
            error_set(err, "its channel list is broken");
            return false;
        }
        ExrChannel *c = &h->channels[h->channel_count++];
        memcpy(c->name, list + at, length + 1);
        const unsigned char *p = end + 1;
        c->type = (int)exr_le32(p);
        c->x_sampling = (int)exr_le32(p + 8);
        c->y_sampling = (int)exr_le32(p + 12);
        if (c->type < EXR_UINT || c->type > EXR_FLOAT || c->x_sampling < 1 || c->y_sampling < 1) {
            error_set(err, "its channel list is broken");
            return false;
        }
        at += (uint32_t)length + 1 + 16;
    }
    return true;
}

/* Reads the header of the OpenEXR file f (from its start) into h (to free with
 * exr_header_free, whatever the result); false (in err) when it is not one or is broken.
 * Of a multi-part file only the number of parts is read; of a deep one, that it is deep. */
bool exr_read_header(FILE *f, ExrHeader *h, Error *err)
{
    *h = (ExrHeader){.parts = 1};
    unsigned char start[8];
    if (fseeko(f, 0, SEEK_SET) != 0 || !read_exactly(f, start, 8, err))
        return false;
    uint32_t version = exr_le32(start + 4);
    if (memcmp(start, EXR_MAGIC, 4) != 0 || (version & 0xff) != 2) {
        error_set(err, "not an OpenEXR file of version 2");
        return false;
    }
    h->tiled = (version & 0x200) != 0;
    h->deep = (version & 0x800) != 0;
    if (!read_attributes(f, h, true, err))
        return false;
    /* A multi-part file: headers one after the other, up to an empty one. */
    if (version & 0x1000) {
        for (;;) {
            int c = getc(f);
            if (c == '\0')
                break;
            if (c == EOF || ungetc(c, f) == EOF) {
                error_set(err, "the file ends in its header");
                return false;
            }
            if (!read_attributes(f, h, false, err))
                return false;
            h->parts++;
        }
        return true;
    }
    uint32_t size;
    const unsigned char *type = exr_attribute(h, "type", "string", &size);
    if (type != NULL && size >= 4 && memcmp(type, "deep", 4) == 0)
        h->deep = true;
    const unsigned char *list = exr_attribute(h, "channels", "chlist", &size);
    if (list == NULL || !read_channels(list, size, h, err)) {
        if (list == NULL)
            error_set(err, "its header has no channel list");
        return false;
    }
    const unsigned char *c = exr_attribute(h, "compression", "compression", &size);
    const unsigned char *w = exr_attribute(h, "dataWindow", "box2i", &size);
    if (c == NULL || w == NULL || size != 16) {
        error_set(err, "its header lacks a compression or a data window");
        return false;
    }
    h->compression = c[0];
    h->x0 = (int32_t)exr_le32(w);
    h->y0 = (int32_t)exr_le32(w + 4);
    h->width = (long)(int32_t)exr_le32(w + 8) - h->x0 + 1;
    h->height = (long)(int32_t)exr_le32(w + 12) - h->y0 + 1;
    off_t end = ftello(f);
    h->table = end;
    return end >= 0;
}

/* Frees what exr_read_header allocated. */
void exr_header_free(ExrHeader *h)
{
    free(h->channels);
    free(h->attributes);
    *h = (ExrHeader){0};
}

/* Tells whether exr_read_pixels reads the file's pixels: a single part of scanlines,
 * compressed with NONE, RLE, ZIPS or ZIP. */
bool exr_decodes(const ExrHeader *h)
{
    return h->parts == 1 && !h->deep && !h->tiled && h->compression <= EXR_ZIP;
}

/* Returns a divided by b (b > 0), rounded down. */
static long floor_div(long a, long b)
{
    return a >= 0 ? a / b : -((-a + b - 1) / b);
}

/* Returns the samples of channel c in line y (none on a line it skips). */
static long samples_in_line(const ExrHeader *h, const ExrChannel *c, long y)
{
    if (y - floor_div(y, c->y_sampling) * c->y_sampling != 0)
        return 0;
    return floor_div(h->x0 + h->width - 1, c->x_sampling) - floor_div(h->x0 - 1, c->x_sampling);
}

/* Undoes RLE: runs of a repeated byte (count - 1, then the byte) and of bytes as they
 * are (-count, then the bytes); false unless exactly n bytes come out. */
static bool unrle(const unsigned char *in, size_t size, unsigned char *out, size_t n)
{
    size_t done = 0;
    for (size_t k = 0; k < size;) {
        int count = (signed char)in[k++];
        if (count < 0) {
            size_t run = (size_t)-count;
            if (k + run > size || done + run > n)
                return false;
            memcpy(out + done, in + k, run);
            k += run;
            done += run;
        } else {
            if (k >= size || done + (size_t)count + 1 > n)
                return false;
            memset(out + done, in[k++], (size_t)count + 1);
            done += (size_t)count + 1;
        }
    }
    return done == n;
}

/* Undoes ZIP's and RLE's preparation of n bytes (see exr.c): the differences summed, then
 * the first and second halves interleaved again, into out. */
static void unprepare(unsigned char *in, size_t n, unsigned char *out)
{
    for (size_t k = 1; k < n; k++)
        in[k] = (unsigned char)(in[k - 1] + in[k] - 128);
    size_t half = (n + 1) / 2;
    for (size_t k = 0; k < half; k++)
        out[2 * k] = in[k];
    for (size_t k = 0; k < n / 2; k++)
        out[2 * k + 1] = in[half + k];
}

/* Turns the chunk's packed bytes (packed of them in in) into its n raw bytes in out;
 * false when they do not decompress to exactly n bytes. */
static bool unpack(const ExrHeader *h, unsigned char *in, size_t packed, unsigned char *work,
                   unsigned char *out, size_t n)
{
    if (packed == n) { /* stored as they are */
        memcpy(out, in, n);
        return true;
    }
    if (h->compression == EXR_NONE || packed > n)
        return false;
    if (h->compression == EXR_RLE) {
        if (!unrle(in, packed, work, n))
            return false;
    } else {
        uLongf size = (uLongf)n;
        if (uncompress(work, &size, in, (uLong)packed) != Z_OK || size != n)
            return false;
    }
    unprepare(work, n, out);
    return true;
}

/* Stores the samples of lines y to y + lines - 1, laid out in raw, into the targets. */
static void scatter(const ExrHeader *h, const unsigned char *raw, long y, long lines,
                    const ExrTarget *targets)
{
    for (long line = y; line < y + lines; line++)
        for (int c = 0; c < h->channel_count; c++) {
            const ExrChannel *ch = &h->channels[c];
            long n = samples_in_line(h, ch, line);
            int bytes = ch->type == EXR_HALF ? 2 : 4;
            if (targets[c].first != NULL) {
                float *out = targets[c].first + (line - h->y0) * h->width * targets[c].step;
                int step = targets[c].step;
                const unsigned char *p = raw;
                if (ch->type == EXR_HALF)
                    for (long x = 0; x < n; x++, p += 2)
                        out[x * step] = exr_half_to_float((uint16_t)(p[0] | p[1] << 8));
                else if (ch->type == EXR_UINT)
                    for (long x = 0; x < n; x++, p += 4)
                        out[x * step] = (float)exr_le32(p);
                else
                    for (long x = 0; x < n; x++, p += 4) {
                        uint32_t bits = exr_le32(p);
                        memcpy(&out[x * step], &bits, sizeof bits);
                    }
            }
            raw += n * bytes;
        }
}

/* Reads the pixels of the file f, whose header is h (exr_decodes is true), into the
 * targets, one a channel (a channel with a target is sampled 1 x 1): each chunk found
 * through the offset table, checked to be the chunk of its lines and to hold exactly their
 * bytes; false (in err) otherwise. */
bool exr_read_pixels(FILE *f, const ExrHeader *h, const ExrTarget *targets, Error *err)
{
    long lines = lines_per_chunk[h->compression];
    long chunks = (h->height + lines - 1) / lines;
    off_t file_size;
    if (fseeko(f, 0, SEEK_END) != 0 || (file_size = ftello(f)) < 0) {
        error_set(err, "%s", strerror(errno));
        return false;
    }
    /* The largest chunk's raw bytes, three times: packed, worked on, raw. */
    long most = 0;
    for (int c = 0; c < h->channel_count; c++)
        most += (h->width + 1) * (h->channels[c].type == EXR_HALF ? 2 : 4);
    most *= lines;
    if (most > MAX_CHUNK_BYTES) {
        error_set(err, "its chunks of %ld lines are larger than %ld bytes", lines, MAX_CHUNK_BYTES);
        return false;
    }
    unsigned char *in = malloc((size_t)most + 1), *work = malloc((size_t)most + 1);
    unsigned char *raw = malloc((size_t)most + 1);
    bool ok = in != NULL && work != NULL && raw != NULL;
    if (!ok)
        error_set(err, "out of memory");
    for (long k = 0; ok && k < chunks; k++) {
        long y = h->y0 + k * lines, count = y + lines <= h->y0 + h->height ? lines : h->y0 + h->height - y;
        size_t need = 0;
        for (long line = y; line < y + count; line++)
            for (int c = 0; c < h->channel_count; c++)
                need += (size_t)samples_in_line(h, &h->channels[c], line) *
                        (h->channels[c].type == EXR_HALF ? 2 : 4);
        char name[64];
        snprintf(name, sizeof name, "the chunk of lines %ld to %ld", y, y + count - 1);
        unsigned char entry[8], leader[8];
        ok = fseeko(f, h->table + 8 * k, SEEK_SET) == 0 && fread(entry, 1, 8, f) == 8;
        uint64_t offset = exr_le32(entry) | (uint64_t)exr_le32(entry + 4) << 32;
        if (!ok || offset < (uint64_t)h->table + 8 * (uint64_t)chunks ||
            offset + 8 > (uint64_t)file_size) {
            error_set(err, "its offset table does not give where %s is", name);
            ok = false;
            break;
        }
        ok = fseeko(f, (off_t)offset, SEEK_SET) == 0 && fread(leader, 1, 8, f) == 8;
        uint32_t packed = exr_le32(leader + 4);
        if (!ok || (int32_t)exr_le32(leader) != y) {
            error_set(err, "%s is not where its offset table says", name);
            ok = false;
        } else if (packed == 0 || packed > need || (h->compression == EXR_NONE && packed != need) ||
                   offset + 8 + packed > (uint64_t)file_size) {
            error_set(err, "%s holds %lu bytes, its lines need %zu%s%s", name,
                      (unsigned long)packed, need,
                      h->compression == EXR_NONE ? " (uncompressed)" : "",
                      offset + 8 + packed > (uint64_t)file_size ? ", beyond the end of the file" : "");
            ok = false;
        } else if (fread(in, 1, packed, f) != packed || !unpack(h, in, packed, work, raw, need)) {
            error_set(err, "%s does not decompress to the %zu bytes of its lines", name, need);
            ok = false;
        } else {
            scatter(h, raw, y, count, targets);
        }
    }
    free(in);
    free(work);
    free(raw);
    return ok;
}
