/* mcref.c: a Monte Carlo render's statistical reference, written and read as OpenEXR. */
#include "mcref.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "exr.h"
#include "exr_read.h"
#include "outfile.h"

/* The prefix of each plane's channels: R, G, B; variance.R, ... (docs/grading.md). */
static const char *const prefixes[MCREF_PLANES] = {"", "variance.", "code.", "codevariance."};

/* The header attribute that marks a file as a statistical reference: its format's version. */
#define MCREF_MARK "raytraStatistics"
#define MCREF_VERSION 1

/* Allocates ref's planes for a width x height image, zeroed; false when out of memory. */
bool mcref_init(McRef *ref, int width, int height)
{
    *ref = (McRef){.width = width, .height = height};
    for (int p = 0; p < MCREF_PLANES; p++)
        if ((ref->plane[p] = calloc(3 * (size_t)width * (size_t)height, sizeof(float))) == NULL) {
            mcref_free(ref);
            return false;
        }
    return true;
}

/* Frees ref's planes. */
void mcref_free(McRef *ref)
{
    for (int p = 0; p < MCREF_PLANES; p++)
        free(ref->plane[p]);
    *ref = (McRef){0};
}

/* Returns where channel name lives in ref, from column x0 and row y0 on: its plane and RGB
 * offset; NULL for a channel that is none of ref's. */
static float *channel_at(const McRef *ref, const char *name, int x0, int y0)
{
    for (int p = 0; p < MCREF_PLANES; p++) {
        size_t n = strlen(prefixes[p]);
        const char *rgb = "RGB", *at = strncmp(name, prefixes[p], n) == 0 ? name + n : NULL;
        if (at != NULL && at[0] != '\0' && at[1] == '\0' && strchr(rgb, at[0]) != NULL)
            return ref->plane[p] + 3 * ((long)y0 * ref->width + x0) + (strchr(rgb, at[0]) - rgb);
    }
    return NULL;
}

/* Writes ref to path as an OpenEXR file of one scanline part, 32-bit floats, ZIP (lossless),
 * through a temporary named path only when complete, so that path is never half-written;
 * false (in err) on failure. */
bool mcref_write(const McRef *ref, const char *path, Error *err)
{
    char names[MCREF_PLANES * 3][32];
    ExrPlane planes[MCREF_PLANES * 3];
    for (int p = 0; p < MCREF_PLANES; p++)
        for (int c = 0; c < 3; c++) {
            char *name = names[3 * p + c];
            snprintf(name, sizeof names[0], "%s%c", prefixes[p], "RGB"[c]);
            planes[3 * p + c] = (ExrPlane){name, ref->plane[p] + c, 3};
        }
    const ExrAttribute attributes[] = {
        {MCREF_MARK, MCREF_VERSION, NULL}, {"P", ref->p, NULL}, {"S", ref->s, NULL},
        {"meanSamples", ref->mean_samples, NULL}, {"varianceSamples", ref->variance_samples, NULL},
        {"seeds", 0, ref->seeds}};
    OutFile out;
    if (!outfile_open(&out, path, err))
        return false;
    if (!exr_write(out.file, ref->width, ref->height, planes, MCREF_PLANES * 3, attributes,
                   (int)(sizeof attributes / sizeof attributes[0]), err)) {
        outfile_abort(&out);
        return false;
    }
    return outfile_commit(&out, err);
}

/* Tells whether path is an OpenEXR file marked as a statistical reference. */
bool mcref_is(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (f == NULL)
        return false;
    ExrHeader h;
    Error err;
    int32_t version = 0;
    bool is = exr_read_header(f, &h, &err) && h.parts == 1 &&
              exr_attribute_int(&h, MCREF_MARK, &version) && version == MCREF_VERSION;
    exr_header_free(&h);
    fclose(f);
    return is;
}

/* Reads the header's figures into ref and checks that every channel is there as floats;
 * points targets at ref's planes. */
static bool read_header(const ExrHeader *h, McRef *ref, ExrTarget *targets, Error *err)
{
    int32_t v[4];
    uint32_t length = 0;
    const unsigned char *seeds = exr_attribute(h, "seeds", "string", &length);
    if (!exr_attribute_int(h, "P", &v[0]) || !exr_attribute_int(h, "S", &v[1]) ||
        !exr_attribute_int(h, "meanSamples", &v[2]) ||
        !exr_attribute_int(h, "varianceSamples", &v[3]) || seeds == NULL) {
        error_set(err, "it lacks the attributes of a statistical reference (P, S, meanSamples, "
                       "varianceSamples, seeds)");
        return false;
    }
    ref->p = v[0], ref->s = v[1], ref->mean_samples = v[2], ref->variance_samples = v[3];
    snprintf(ref->seeds, sizeof ref->seeds, "%.*s", (int)(length < 63 ? length : 63),
             (const char *)seeds);
    if (ref->mean_samples < 1 || ref->variance_samples < 2) {
        error_set(err, "a statistical reference needs 1 render for its mean and 2 for its "
                       "variances at least");
        return false;
    }
    int found = 0;
    for (int c = 0; c < h->channel_count; c++) {
        const ExrChannel *e = &h->channels[c];
        float *at = channel_at(ref, e->name, 0, 0);
        if (at == NULL)
            continue;
        if (e->type != EXR_FLOAT || e->x_sampling != 1 || e->y_sampling != 1) {
            error_set(err, "channel %s is not of full-resolution floats", e->name);
            return false;
        }
        targets[c] = (ExrTarget){at, 3};
        found++;
    }
    if (found != 3 * MCREF_PLANES)
        error_set(err, "%d of its %d channels are missing", 3 * MCREF_PLANES - found,
                  3 * MCREF_PLANES);
    return found == 3 * MCREF_PLANES;
}

/* Reads the statistical reference at path into ref (left empty on failure); false (in err)
 * when it is not one or cannot be read. */
bool mcref_read(McRef *ref, const char *path, Error *err)
{
    *ref = (McRef){0};
    FILE *f = fopen(path, "rb");
    if (f == NULL) {
        error_set(err, "%s", strerror(errno));
        return false;
    }
    ExrHeader h;
    ExrTarget *targets = NULL;
    bool ok = exr_read_header(f, &h, err);
    if (ok && !exr_decodes(&h)) {
        error_set(err, "a statistical reference is a single part of scanlines, compressed with "
                       "NONE, RLE, ZIPS or ZIP");
        ok = false;
    }
    if (ok && (h.width < 1 || h.height < 1 || h.width * h.height > (1L << 26))) {
        error_set(err, "a statistical reference of %ld x %ld pixels", h.width, h.height);
        ok = false;
    }
    if (ok && !mcref_init(ref, (int)h.width, (int)h.height)) {
        error_set(err, "out of memory for a %ld x %ld reference", h.width, h.height);
        ok = false;
    }
    if (ok && (targets = calloc((size_t)h.channel_count + 1, sizeof *targets)) == NULL) {
        error_set(err, "out of memory");
        ok = false;
    }
    ok = ok && read_header(&h, ref, targets, err) && exr_read_pixels(f, &h, targets, err);
    free(targets);
    exr_header_free(&h);
    fclose(f);
    if (!ok)
        mcref_free(ref);
    return ok;
}
