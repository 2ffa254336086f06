/* exr_header.c: reading an OpenEXR file's header: its attributes, its channel list, its layout. */
#include "exr_header.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>

/* The limits of what is read: no header or channel list asks for more memory. */
#define MAX_HEADER_BYTES (16L << 20)
#define MAX_CHANNELS 1024

/* Returns the little-endian 32-bit integer at p. */
uint32_t exr_le32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
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
