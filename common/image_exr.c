/* image_exr.c: writing and reading OpenEXR through the library's C API (OpenEXRCore). */
#include "image.h"

#include <errno.h>
#include <openexr.h>
#include <stdint.h>
#include <string.h>
#include <unistd.h>

#include "stop.h"

/* What the library's callbacks share with the functions below. */
typedef struct {
    int fd;     /* where a write goes (the temporary of outfile.c) */
    Error *err; /* the first message the library gave */
    bool failed;
} ExrIo;

/* The library's error handler: keeps the first message, prints nothing. */
static void on_error(exr_const_context_t ctxt, exr_result_t code, const char *message)
{
    void *data = NULL;
    exr_get_user_data(ctxt, &data);
    ExrIo *io = data;
    if (io != NULL && !io->failed) {
        io->failed = true;
        error_set(io->err, "%s", message != NULL ? message : exr_get_default_error_message(code));
    }
}

/* The library's write function: the bytes at their offset in the file, all of them. */
static int64_t write_bytes(exr_const_context_t ctxt, void *data, const void *buffer,
                           uint64_t size, uint64_t offset, exr_stream_error_func_ptr_t error_cb)
{
    ExrIo *io = data;
    const char *p = buffer;
    for (uint64_t done = 0; done < size;) {
        ssize_t n = pwrite(io->fd, p + done, size - done, (off_t)(offset + done));
        if (n < 0 && errno == EINTR && !stop_requested())
            continue;
        if (n <= 0) {
            error_cb(ctxt, EXR_ERR_WRITE_IO, "%s", n < 0 ? strerror(errno) : "nothing written");
            return -1;
        }
        done += (uint64_t)n;
    }
    return (int64_t)size;
}

/* Returns the offset (0, 1 or 2) of channel name in an RGB pixel, or -1 for another. */
static int rgb_offset(const char *name)
{
    static const char *const rgb[] = {"R", "G", "B"};
    for (int k = 0; k < 3; k++)
        if (strcmp(name, rgb[k]) == 0)
            return k;
    return -1;
}

/* Points every channel of a coding pipeline at img (as floats) from column x0, row y0 on:
 * R, G and B at their place in the RGB pixel, Y at R (copied to G and B after), others
 * nowhere. */
static void point_channels(exr_coding_channel_info_t *channels, int count, const Image *img,
                           int x0, int y0, bool decoding)
{
    for (int c = 0; c < count; c++) {
        exr_coding_channel_info_t *ch = &channels[c];
        int k = rgb_offset(ch->channel_name);
        if (k < 0 && decoding && strcmp(ch->channel_name, "Y") == 0)
            k = 0;
        uint8_t *at =
            k < 0 ? NULL : (uint8_t *)(img->pixels + 3 * ((long)y0 * img->width + x0) + k);
        if (decoding)
            ch->decode_to_ptr = at;
        else
            ch->encode_from_ptr = at;
        ch->user_pixel_stride = 3 * (int32_t)sizeof(float);
        ch->user_line_stride = 3 * (int32_t)sizeof(float) * img->width;
        ch->user_data_type = EXR_PIXEL_FLOAT;
        ch->user_bytes_per_element = sizeof(float);
    }
}

/* Describes a failure of the library, unless on_error already did. */
static bool failed(ExrIo *io, exr_result_t result)
{
    if (result == EXR_ERR_SUCCESS)
        return false;
    if (!io->failed) {
        io->failed = true;
        error_set(io->err, "%s", exr_get_default_error_message(result));
    }
    return true;
}

/* Writes the scanline chunks of img through the open context; false (in io) on failure. */
static bool write_chunks(exr_context_t ctxt, int part, const Image *img, ExrIo *io)
{
    int32_t lines;
    if (failed(io, exr_write_header(ctxt)) ||
        failed(io, exr_get_scanlines_per_chunk(ctxt, part, &lines)))
        return false;
    exr_encode_pipeline_t encoder = EXR_ENCODE_PIPELINE_INITIALIZER;
    bool started = false, ok = true;
    for (int y = 0; ok && y < img->height; y += lines) {
        /* A stop request ends the writing between chunks: the temporary is then removed. */
        if (stop_requested()) {
            error_set(io->err, "interrupted");
            io->failed = true;
            ok = false;
            break;
        }
        exr_chunk_info_t chunk;
        ok = !failed(io, exr_write_scanline_chunk_info(ctxt, part, y, &chunk));
        if (ok && !started) {
            ok = !failed(io, exr_encoding_initialize(ctxt, part, &chunk, &encoder));
            started = ok;
            point_channels(encoder.channels, encoder.channel_count, img, 0, y, false);
            ok = ok && !failed(io, exr_encoding_choose_default_routines(ctxt, part, &encoder));
        } else if (ok) {
            ok = !failed(io, exr_encoding_update(ctxt, part, &chunk, &encoder));
            point_channels(encoder.channels, encoder.channel_count, img, 0, y, false);
        }
        ok = ok && !failed(io, exr_encoding_run(ctxt, part, &encoder));
    }
    if (started)
        exr_encoding_destroy(ctxt, &encoder);
    return ok;
}

/* Writes img to f as an OpenEXR image: linear 32-bit float R, G and B channels, lossless
 * ZIP compression, one part of scanlines. Floats, not halves: halves hold nothing above
 * 65504, and a float image is the PFM's values exactly. */
bool image_write_exr(const Image *img, FILE *f, Error *err)
{
    /* The library writes at offsets through the descriptor: nothing may wait in f. */
    if (fflush(f) != 0) {
        error_set(err, "%s", strerror(errno));
        return false;
    }
    ExrIo io = {.fd = fileno(f), .err = err};
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = on_error;
    init.user_data = &io;
    init.write_fn = write_bytes;
    exr_context_t ctxt = NULL;
    int part = 0;
    bool ok = !failed(&io, exr_start_write(&ctxt, "image", EXR_WRITE_FILE_DIRECTLY, &init)) &&
              !failed(&io, exr_add_part(ctxt, "rgb", EXR_STORAGE_SCANLINE, &part)) &&
              !failed(&io, exr_initialize_required_attr_simple(ctxt, part, img->width,
                                                               img->height, EXR_COMPRESSION_ZIP));
    static const char *const names[] = {"R", "G", "B"};
    for (int k = 0; ok && k < 3; k++)
        ok = !failed(&io, exr_add_channel(ctxt, part, names[k], EXR_PIXEL_FLOAT,
                                          EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1));
    ok = ok && write_chunks(ctxt, part, img, &io);
    if (ctxt != NULL && failed(&io, exr_finish(&ctxt)))
        ok = false;
    return ok;
}

/* Finds the channels of part 0 raytra reads (R, G and B, or Y), checking that it can:
 * scanlines or tiles (not deep data), float or half samples, no subsampling; false (in
 * io) otherwise. */
static bool check_channels(exr_context_t ctxt, ExrIo *io, bool *grey, bool *tiled)
{
    exr_storage_t storage;
    const exr_attr_chlist_t *list;
    if (failed(io, exr_get_storage(ctxt, 0, &storage)) ||
        failed(io, exr_get_channels(ctxt, 0, &list)))
        return false;
    if (storage != EXR_STORAGE_SCANLINE && storage != EXR_STORAGE_TILED) {
        error_set(io->err, "deep OpenEXR images cannot be read, only scanline and tiled ones");
        return false;
    }
    *tiled = storage == EXR_STORAGE_TILED;
    int rgb = 0, y = 0;
    for (int c = 0; c < list->num_channels; c++) {
        const exr_attr_chlist_entry_t *e = &list->entries[c];
        bool used = rgb_offset(e->name.str) >= 0 || strcmp(e->name.str, "Y") == 0;
        if (!used)
            continue;
        if (e->pixel_type == EXR_PIXEL_UINT || e->x_sampling != 1 || e->y_sampling != 1) {
            error_set(io->err, "channel %s is %s: not supported", e->name.str,
                      e->pixel_type == EXR_PIXEL_UINT ? "of unsigned integers" : "subsampled");
            return false;
        }
        rgb += rgb_offset(e->name.str) >= 0;
        y += strcmp(e->name.str, "Y") == 0;
    }
    if (rgb != 3 && y != 1) {
        error_set(io->err, "no R, G and B channels, nor a Y channel");
        return false;
    }
    *grey = rgb != 3;
    return true;
}

/* Decodes one chunk, which covers img from column x0, row y0 on, with the decoder (set up
 * by the first chunk, *started then set); false (in io) on failure. */
static bool decode_chunk(exr_context_t ctxt, const exr_chunk_info_t *chunk, Image *img, int x0,
                         int y0, exr_decode_pipeline_t *decoder, bool *started, ExrIo *io)
{
    if (!*started) {
        if (failed(io, exr_decoding_initialize(ctxt, 0, chunk, decoder)))
            return false;
        *started = true;
        point_channels(decoder->channels, decoder->channel_count, img, x0, y0, true);
        if (failed(io, exr_decoding_choose_default_routines(ctxt, 0, decoder)))
            return false;
    } else {
        if (failed(io, exr_decoding_update(ctxt, 0, chunk, decoder)))
            return false;
        point_channels(decoder->channels, decoder->channel_count, img, x0, y0, true);
    }
    return !failed(io, exr_decoding_run(ctxt, 0, decoder));
}

/* Decodes every chunk of part 0 into img: scanline blocks (the data window starts at row
 * top), or the tiles of the full-resolution level. */
static bool read_chunks(exr_context_t ctxt, Image *img, int top, bool tiled, ExrIo *io)
{
    exr_decode_pipeline_t decoder = EXR_DECODE_PIPELINE_INITIALIZER;
    bool started = false, ok = true;
    if (!tiled) {
        int32_t lines;
        ok = !failed(io, exr_get_scanlines_per_chunk(ctxt, 0, &lines));
        for (int y = 0; ok && y < img->height; y += lines) {
            exr_chunk_info_t chunk;
            ok = !failed(io, exr_read_scanline_chunk_info(ctxt, 0, top + y, &chunk)) &&
                 decode_chunk(ctxt, &chunk, img, 0, chunk.start_y - top, &decoder, &started, io);
        }
    } else {
        /* Level (0, 0) is the image itself; mipmap levels below it are not read. */
        int32_t tile_w, tile_h;
        ok = !failed(io, exr_get_tile_sizes(ctxt, 0, 0, 0, &tile_w, &tile_h));
        for (int ty = 0; ok && ty * tile_h < img->height; ty++)
            for (int tx = 0; ok && tx * tile_w < img->width; tx++) {
                exr_chunk_info_t chunk;
                ok = !failed(io, exr_read_tile_chunk_info(ctxt, 0, tx, ty, 0, 0, &chunk)) &&
                     decode_chunk(ctxt, &chunk, img, tx * tile_w, ty * tile_h, &decoder,
                                  &started, io);
            }
    }
    if (started)
        exr_decoding_destroy(ctxt, &decoder);
    return ok;
}

/* Reads the OpenEXR image at path (its first part, scanline or tiled) into img
 * (overwritten; left empty on failure): R, G and B, or Y as grey, converted to float;
 * alpha is not applied, as OpenEXR colours are already multiplied by it. Linear values,
 * as the file holds them. */
bool image_read_exr(Image *img, const char *path, Error *err)
{
    *img = (Image){0};
    ExrIo io = {.fd = -1, .err = err};
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = on_error;
    init.user_data = &io;
    init.max_image_width = IMAGE_MAX_SIDE;
    init.max_image_height = IMAGE_MAX_SIDE;
    init.flags = EXR_CONTEXT_FLAG_SILENT_HEADER_PARSE;
    exr_context_t ctxt = NULL;
    exr_attr_box2i_t window;
    bool grey = false, tiled = false;
    bool ok = !failed(&io, exr_start_read(&ctxt, path, &init)) &&
              !failed(&io, exr_get_data_window(ctxt, 0, &window)) &&
              check_channels(ctxt, &io, &grey, &tiled);
    if (ok) {
        long width = (long)window.max.x - window.min.x + 1;
        long height = (long)window.max.y - window.min.y + 1;
        if (!image_size_ok(width, height)) {
            error_set(err,
                      "the image is %ld x %ld pixels: outside the limits (1 to %d a side, at "
                      "most %ld pixels)",
                      width, height, IMAGE_MAX_SIDE, IMAGE_MAX_PIXELS);
            ok = false;
        } else if (!image_init(img, (int)width, (int)height)) {
            error_set(err, "out of memory for a %ld x %ld image", width, height);
            ok = false;
        }
    }
    ok = ok && read_chunks(ctxt, img, window.min.y, tiled, &io);
    if (ok && grey)
        for (long k = 0; k < (long)img->width * img->height; k++)
            img->pixels[3 * k + 1] = img->pixels[3 * k + 2] = img->pixels[3 * k];
    if (ctxt != NULL)
        exr_finish(&ctxt);
    if (!ok)
        image_free(img);
    return ok;
}
