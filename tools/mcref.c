/* mcref.c: a Monte Carlo render's statistical reference, written and read with OpenEXR's C API. */
#include "mcref.h"

#include <errno.h>
#include <openexr.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The prefix of each plane's channels: R, G, B; variance.R, ... (docs/grading.md). */
static const char *const prefixes[MCREF_PLANES] = {"", "variance.", "code.", "codevariance."};

/* The header attribute that marks a file as a statistical reference: its format's version. */
#define MCREF_MARK "raytraStatistics"
#define MCREF_VERSION 1

/* What the library's callbacks share with the functions below. */
typedef struct {
    Error *err;
    bool failed;
} RefIo;

/* The library's error handler: keeps the first message, prints nothing. */
static void on_error(exr_const_context_t ctxt, exr_result_t code, const char *message)
{
    void *data = NULL;
    exr_get_user_data(ctxt, &data);
    RefIo *io = data;
    if (io != NULL && !io->failed && io->err != NULL) {
        io->failed = true;
        error_set(io->err, "%s", message != NULL ? message : exr_get_default_error_message(code));
    }
}

/* Describes a failure of the library, unless on_error already did; true when it failed. */
static bool failed(RefIo *io, exr_result_t result)
{
    if (result == EXR_ERR_SUCCESS)
        return false;
    if (!io->failed && io->err != NULL)
        error_set(io->err, "%s", exr_get_default_error_message(result));
    io->failed = true;
    return true;
}

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

/* Points every channel of a coding pipeline at ref's planes from row y0 on. */
static void point_channels(exr_coding_channel_info_t *channels, int count, const McRef *ref, int y0,
                           bool decoding)
{
    for (int c = 0; c < count; c++) {
        exr_coding_channel_info_t *ch = &channels[c];
        uint8_t *at = (uint8_t *)channel_at(ref, ch->channel_name, 0, y0);
        if (decoding)
            ch->decode_to_ptr = at;
        else
            ch->encode_from_ptr = at;
        ch->user_pixel_stride = 3 * (int32_t)sizeof(float);
        ch->user_line_stride = 3 * (int32_t)sizeof(float) * ref->width;
        ch->user_data_type = EXR_PIXEL_FLOAT;
        ch->user_bytes_per_element = sizeof(float);
    }
}

/* Writes the header's attributes and channels of ref into part 0 of ctxt. */
static bool write_header(exr_context_t ctxt, const McRef *ref, RefIo *io)
{
    int part = 0;
    bool ok = !failed(io, exr_add_part(ctxt, "statistics", EXR_STORAGE_SCANLINE, &part)) &&
              !failed(io, exr_initialize_required_attr_simple(ctxt, part, ref->width, ref->height,
                                                              EXR_COMPRESSION_ZIP)) &&
              !failed(io, exr_attr_set_int(ctxt, part, MCREF_MARK, MCREF_VERSION)) &&
              !failed(io, exr_attr_set_int(ctxt, part, "P", ref->p)) &&
              !failed(io, exr_attr_set_int(ctxt, part, "S", ref->s)) &&
              !failed(io, exr_attr_set_int(ctxt, part, "meanSamples", ref->mean_samples)) &&
              !failed(io, exr_attr_set_int(ctxt, part, "varianceSamples", ref->variance_samples)) &&
              !failed(io, exr_attr_set_string(ctxt, part, "seeds", ref->seeds));
    for (int p = 0; ok && p < MCREF_PLANES; p++)
        for (int c = 0; ok && c < 3; c++) {
            char name[32];
            snprintf(name, sizeof name, "%s%c", prefixes[p], "RGB"[c]);
            ok = !failed(io, exr_add_channel(ctxt, part, name, EXR_PIXEL_FLOAT,
                                             EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1));
        }
    return ok && !failed(io, exr_write_header(ctxt));
}

/* Writes ref to path as an OpenEXR file of one scanline part, 32-bit floats, ZIP (lossless),
 * through a temporary renamed at the end, so that path is never half-written; false (in
 * err) on failure. */
bool mcref_write(const McRef *ref, const char *path, Error *err)
{
    RefIo io = {.err = err};
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = on_error;
    init.user_data = &io;
    exr_context_t ctxt = NULL;
    char temporary[4096];
    if (snprintf(temporary, sizeof temporary, "%s.part", path) >= (int)sizeof temporary) {
        error_set(err, "the path is too long");
        return false;
    }
    bool ok = !failed(&io, exr_start_write(&ctxt, temporary, EXR_WRITE_FILE_DIRECTLY, &init)) &&
              write_header(ctxt, ref, &io);
    int32_t lines = 1;
    ok = ok && !failed(&io, exr_get_scanlines_per_chunk(ctxt, 0, &lines));
    exr_encode_pipeline_t encoder = EXR_ENCODE_PIPELINE_INITIALIZER;
    bool started = false;
    for (int y = 0; ok && y < ref->height; y += lines) {
        exr_chunk_info_t chunk;
        ok = !failed(&io, exr_write_scanline_chunk_info(ctxt, 0, y, &chunk));
        if (ok && !started) {
            ok = !failed(&io, exr_encoding_initialize(ctxt, 0, &chunk, &encoder));
            started = ok;
            point_channels(encoder.channels, encoder.channel_count, ref, y, false);
            ok = ok && !failed(&io, exr_encoding_choose_default_routines(ctxt, 0, &encoder));
        } else if (ok) {
            ok = !failed(&io, exr_encoding_update(ctxt, 0, &chunk, &encoder));
            point_channels(encoder.channels, encoder.channel_count, ref, y, false);
        }
        ok = ok && !failed(&io, exr_encoding_run(ctxt, 0, &encoder));
    }
    if (started)
        exr_encoding_destroy(ctxt, &encoder);
    if (ctxt != NULL && failed(&io, exr_finish(&ctxt)))
        ok = false;
    /* The temporary becomes path only when everything was written. */
    if (ok && rename(temporary, path) != 0) {
        error_set(err, "cannot rename %s: %s", temporary, strerror(errno));
        ok = false;
    }
    if (!ok)
        remove(temporary);
    return ok;
}

/* Opens path's header for reading, quietly; NULL (in io) when it cannot. */
static exr_context_t open_header(const char *path, RefIo *io)
{
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = on_error;
    init.user_data = io;
    init.max_image_width = 32768;
    init.max_image_height = 32768;
    init.flags = EXR_CONTEXT_FLAG_SILENT_HEADER_PARSE;
    exr_context_t ctxt = NULL;
    if (failed(io, exr_start_read(&ctxt, path, &init)) && ctxt != NULL)
        exr_finish(&ctxt);
    return ctxt;
}

/* Tells whether path is an OpenEXR file marked as a statistical reference. */
bool mcref_is(const char *path)
{
    RefIo io = {0};
    exr_context_t ctxt = open_header(path, &io);
    int32_t version = 0;
    bool is = ctxt != NULL && exr_attr_get_int(ctxt, 0, MCREF_MARK, &version) == EXR_ERR_SUCCESS;
    if (ctxt != NULL)
        exr_finish(&ctxt);
    return is && version == MCREF_VERSION;
}

/* Reads the header's figures into ref and checks that every channel is there as floats. */
static bool read_header(exr_context_t ctxt, McRef *ref, RefIo *io)
{
    const char *seeds = NULL;
    int32_t length = 0;
    int32_t v[4];
    bool ok = !failed(io, exr_attr_get_int(ctxt, 0, "P", &v[0])) &&
              !failed(io, exr_attr_get_int(ctxt, 0, "S", &v[1])) &&
              !failed(io, exr_attr_get_int(ctxt, 0, "meanSamples", &v[2])) &&
              !failed(io, exr_attr_get_int(ctxt, 0, "varianceSamples", &v[3])) &&
              !failed(io, exr_attr_get_string(ctxt, 0, "seeds", &length, &seeds));
    if (!ok)
        return false;
    ref->p = v[0], ref->s = v[1], ref->mean_samples = v[2], ref->variance_samples = v[3];
    snprintf(ref->seeds, sizeof ref->seeds, "%.*s", (int)length, seeds);
    if (ref->mean_samples < 1 || ref->variance_samples < 2) {
        error_set(io->err, "a statistical reference needs 1 render for its mean and 2 for its "
                           "variances at least");
        return false;
    }
    const exr_attr_chlist_t *list;
    if (failed(io, exr_get_channels(ctxt, 0, &list)))
        return false;
    int found = 0;
    for (int c = 0; c < list->num_channels; c++) {
        const exr_attr_chlist_entry_t *e = &list->entries[c];
        if (channel_at(ref, e->name.str, 0, 0) == NULL)
            continue;
        if (e->pixel_type != EXR_PIXEL_FLOAT || e->x_sampling != 1 || e->y_sampling != 1) {
            error_set(io->err, "channel %s is not of full-resolution floats", e->name.str);
            return false;
        }
        found++;
    }
    if (found != 3 * MCREF_PLANES)
        error_set(io->err, "%d of its %d channels are missing", 3 * MCREF_PLANES - found,
                  3 * MCREF_PLANES);
    return found == 3 * MCREF_PLANES;
}

/* Reads the statistical reference at path into ref (left empty on failure); false (in err)
 * when it is not one or cannot be read. */
bool mcref_read(McRef *ref, const char *path, Error *err)
{
    *ref = (McRef){0};
    RefIo io = {.err = err};
    exr_context_t ctxt = open_header(path, &io);
    exr_storage_t storage;
    exr_attr_box2i_t window;
    bool ok = ctxt != NULL && !failed(&io, exr_get_storage(ctxt, 0, &storage)) &&
              !failed(&io, exr_get_data_window(ctxt, 0, &window));
    if (ok && storage != EXR_STORAGE_SCANLINE) {
        error_set(err, "a statistical reference is a scanline image");
        ok = false;
    }
    long width = ok ? (long)window.max.x - window.min.x + 1 : 0;
    long height = ok ? (long)window.max.y - window.min.y + 1 : 0;
    if (ok && (width < 1 || height < 1 || width * height > (1L << 26))) {
        error_set(err, "a statistical reference of %ld x %ld pixels", width, height);
        ok = false;
    }
    if (ok && !mcref_init(ref, (int)width, (int)height)) {
        error_set(err, "out of memory for a %ld x %ld reference", width, height);
        ok = false;
    }
    ok = ok && read_header(ctxt, ref, &io);
    int32_t lines = 1;
    ok = ok && !failed(&io, exr_get_scanlines_per_chunk(ctxt, 0, &lines));
    exr_decode_pipeline_t decoder = EXR_DECODE_PIPELINE_INITIALIZER;
    bool started = false;
    for (int y = 0; ok && y < ref->height; y += lines) {
        exr_chunk_info_t chunk;
        ok = !failed(&io, exr_read_scanline_chunk_info(ctxt, 0, window.min.y + y, &chunk));
        if (ok && !started) {
            ok = !failed(&io, exr_decoding_initialize(ctxt, 0, &chunk, &decoder));
            started = ok;
        } else if (ok)
            ok = !failed(&io, exr_decoding_update(ctxt, 0, &chunk, &decoder));
        if (ok)
            point_channels(decoder.channels, decoder.channel_count, ref,
                           chunk.start_y - window.min.y, true);
        if (ok && y == 0)
            ok = !failed(&io, exr_decoding_choose_default_routines(ctxt, 0, &decoder));
        ok = ok && !failed(&io, exr_decoding_run(ctxt, 0, &decoder));
    }
    if (started)
        exr_decoding_destroy(ctxt, &decoder);
    if (ctxt != NULL)
        exr_finish(&ctxt);
    if (!ok)
        mcref_free(ref);
    return ok;
}
