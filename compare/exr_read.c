/* exr_read.c: reading the pixels of OpenEXR scanline files compressed with NONE, RLE, ZIPS or
 * ZIP (what zlib undoes), every byte checked against what the header says. */
#include "exr_read.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>

#include "exr_unpack.h"

/* The limit of what is read: no chunk asks for more memory. */
#define MAX_CHUNK_BYTES (256L << 20)

/* Lines a chunk holds under each compression from NONE to DWAB. */
static const int lines_per_chunk[10] = {1, 1, 1, 16, 32, 16, 32, 32, 32, 256};

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
        } else if (fread(in, 1, packed, f) != packed ||
                   !exr_unpack(h->compression, in, packed, work, raw, need)) {
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
