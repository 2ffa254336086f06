/* image_exr.c: writing and reading OpenEXR through the library's C API (OpenEXRCore). */
#include "image.h"

#include <errno.h>
#include <float.h>
#include <limits.h>
#include <math.h>
#include <openexr.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "stop.h"

/* What the library's callbacks share with the functions below. */
typedef struct {
    int fd;       /* where a write goes (the temporary of outfile.c) */
    FILE *in;     /* where a read comes from */
    int64_t size; /* of in, in bytes */
    Error *err;   /* the first message the library gave */
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
static int64_t write_bytes(exr_const_context_t ctxt, void *data, const void *buffer, uint64_t size,
                           uint64_t offset, exr_stream_error_func_ptr_t error_cb)
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

/* Points every channel of an encoding pipeline at img (as floats) from row y0 on: R, G and
 * B at their place in the RGB pixel. */
static void point_channels(exr_coding_channel_info_t *channels, int count, const Image *img, int y0)
{
    for (int c = 0; c < count; c++) {
        exr_coding_channel_info_t *ch = &channels[c];
        int k = ch->channel_name[0] == 'R' ? 0 : ch->channel_name[0] == 'G' ? 1 : 2;
        ch->encode_from_ptr = (const uint8_t *)(img->pixels + 3 * (long)y0 * img->width + k);
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
            point_channels(encoder.channels, encoder.channel_count, img, y);
            ok = ok && !failed(io, exr_encoding_choose_default_routines(ctxt, part, &encoder));
        } else if (ok) {
            ok = !failed(io, exr_encoding_update(ctxt, part, &chunk, &encoder));
            point_channels(encoder.channels, encoder.channel_count, img, y);
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
              !failed(&io, exr_initialize_required_attr_simple(ctxt, part, img->width, img->height,
                                                               EXR_COMPRESSION_ZIP));
    static const char *const names[] = {"R", "G", "B"};
    for (int k = 0; ok && k < 3; k++)
        ok = !failed(&io, exr_add_channel(ctxt, part, names[k], EXR_PIXEL_FLOAT,
                                          EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1));
    ok = ok && write_chunks(ctxt, part, img, &io);
    if (ctxt != NULL && failed(&io, exr_finish(&ctxt)))
        ok = false;
    return ok;
}

/* ---- Reading ---------------------------------------------------------------------------- */

/* The library's read function: the bytes at offset in the stream, fewer at its end. */
static int64_t read_bytes(exr_const_context_t ctxt, void *data, void *buffer, uint64_t size,
                          uint64_t offset, exr_stream_error_func_ptr_t error_cb)
{
    ExrIo *io = data;
    if (offset >= (uint64_t)io->size)
        return 0;
    if (fseeko(io->in, (off_t)offset, SEEK_SET) != 0) {
        error_cb(ctxt, EXR_ERR_READ_IO, "%s", strerror(errno));
        return -1;
    }
    size_t n = fread(buffer, 1, size, io->in);
    if (n < size && ferror(io->in)) {
        error_cb(ctxt, EXR_ERR_READ_IO, "%s", strerror(errno));
        return -1;
    }
    return (int64_t)n;
}

/* The library's size function: the stream's length, found when it was opened. */
static int64_t query_size(exr_const_context_t ctxt, void *data)
{
    (void)ctxt;
    return ((ExrIo *)data)->size;
}

/* The library's allocator: zeroed memory, so that no byte a decoder leaves unwritten is
 * ever read as whatever was there before. */
static void *alloc_zeroed(size_t bytes)
{
    return calloc(1, bytes > 0 ? bytes : 1);
}

/* The channel roles raytra knows; a channel of another name is not read. */
typedef enum { ROLE_R, ROLE_G, ROLE_B, ROLE_Y, ROLE_RY, ROLE_BY, ROLE_COUNT, ROLE_NONE } Role;
static const char *const role_names[ROLE_COUNT] = {"R", "G", "B", "Y", "RY", "BY"};

/* The channel layouts raytra reads. */
typedef enum {
    LAYOUT_RGB,  /* R, G and B (any other channel ignored) */
    LAYOUT_GREY, /* Y alone, as grey */
    LAYOUT_YC    /* luminance Y and chroma RY, BY sampled 2 x 2, as RgbaInputFile reads them */
} ExrLayout;

/* How a part is read: its layout, and where the samples of each role go. */
typedef struct {
    ExrLayout layout;
    int x0, y0, width, height; /* the data window */
    bool tiled;
    float *plane[ROLE_COUNT]; /* NULL for a role not read */
    int step[ROLE_COUNT];     /* floats from a sample to the next in a row */
    long stride[ROLE_COUNT];  /* floats from a row to the next */
    int sampling[ROLE_COUNT]; /* 1, or 2 for the chroma */
    float yw[3];              /* the luminance weights of R, G and B (YC) */
} ExrPlan;

/* Returns the role of the channel called name. */
static Role role_of(const char *name)
{
    for (int r = 0; r < ROLE_COUNT; r++)
        if (strcmp(name, role_names[r]) == 0)
            return (Role)r;
    return ROLE_NONE;
}

/* Returns the value of the half (IEEE 754 binary16) with bits h. */
static float half_to_float(uint16_t h)
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

/* Returns the bits of the half nearest to f (ties to even), as OpenEXR's half(float). */
static uint16_t float_to_half(float f)
{
    uint32_t bits;
    memcpy(&bits, &f, sizeof bits);
    uint16_t sign = (uint16_t)((bits >> 16) & 0x8000);
    uint32_t a = bits & 0x7fffffffu;
    if (a >= 0x7f800000u) {
        /* Infinity, or NaN with its leading mantissa bits (at least one set). */
        uint32_t m = (a & 0x7fffff) >> 13;
        return (uint16_t)(sign | 0x7c00 | (a == 0x7f800000u ? 0 : m | (m == 0)));
    }
    if (a >= 0x477ff000u) /* 65520 and above round to infinity */
        return sign | 0x7c00;
    if (a >= 0x38800000u) {
        /* Normal: exponent rebiased by -112, 13 mantissa bits rounded off to even. */
        a -= 0x38000000u;
        return (uint16_t)(sign | ((a + 0xfff + ((a >> 13) & 1)) >> 13));
    }
    if (a <= 0x33000000u) /* at most half the smallest subnormal: zero */
        return sign;
    /* Subnormal: the significand with its implicit 1 shifted right, rounded to even. */
    uint32_t shift = 0x7e - (a >> 23), m = 0x800000u | (a & 0x7fffff);
    uint32_t rest = m << (32 - shift);
    uint16_t h = (uint16_t)(sign | (m >> shift));
    if (rest > 0x80000000u || (rest == 0x80000000u && (h & 1)))
        h++;
    return h;
}

/* Returns f rounded to the nearest half, as a float. */
static float half_round(float f)
{
    return half_to_float(float_to_half(f));
}

/* Copies a channel's name from the file into text (size bytes), cut to fit, each byte that
 * is not printable ASCII as '?': a message never carries a terminal's control codes. */
static void printable_name(const char *name, char *text, size_t size)
{
    size_t k = 0;
    for (; name[k] != '\0' && k + 1 < size; k++)
        text[k] = name[k] >= ' ' && name[k] <= '~' ? name[k] : '?';
    text[k] = '\0';
}

/* Describes a channel list's names in text: "A, Z" (the first eight, then "..."). */
static void channel_names(const exr_attr_chlist_t *list, char *text, size_t size)
{
    snprintf(text, size, "%s", list->num_channels == 0 ? "none" : "");
    for (int c = 0; c < list->num_channels && c <= 8; c++) {
        char name[32];
        printable_name(list->entries[c].name.str, name, sizeof name);
        size_t used = strlen(text);
        snprintf(text + used, size - used, "%s%s", c > 0 ? ", " : "", c < 8 ? name : "...");
    }
}

/* Chooses the layout of part 0 from its channel names and checks that raytra can read the
 * channels it uses: half or float samples, R, G, B and Y at full resolution, RY and BY
 * sampled 2 x 2; false (in io) otherwise. Other channels are not read. */
static bool choose_layout(const exr_attr_chlist_t *list, ExrPlan *plan, ExrIo *io)
{
    const exr_attr_chlist_entry_t *entry[ROLE_COUNT] = {0};
    for (int c = 0; c < list->num_channels; c++) {
        Role r = role_of(list->entries[c].name.str);
        if (r != ROLE_NONE)
            entry[r] = &list->entries[c];
    }
    int rgb = (entry[ROLE_R] != NULL) + (entry[ROLE_G] != NULL) + (entry[ROLE_B] != NULL);
    bool chroma = entry[ROLE_RY] != NULL || entry[ROLE_BY] != NULL;
    char names[320];
    if (rgb == 3) {
        plan->layout = LAYOUT_RGB;
    } else if (rgb > 0) {
        channel_names(list, names, sizeof names);
        error_set(io->err, "it has some of R, G and B but not all three (its channels: %s)", names);
        return false;
    } else if (entry[ROLE_Y] != NULL) {
        plan->layout = chroma ? LAYOUT_YC : LAYOUT_GREY;
    } else {
        channel_names(list, names, sizeof names);
        error_set(io->err, "%s (its channels: %s)",
                  chroma ? "chroma channels RY, BY without the luminance Y"
                         : "no R, G and B channels, nor a Y channel",
                  names);
        return false;
    }
    for (int r = 0; r < ROLE_COUNT; r++) {
        const exr_attr_chlist_entry_t *e = entry[r];
        bool used = plan->layout == LAYOUT_RGB
                        ? r <= ROLE_B
                        : r == ROLE_Y || (plan->layout == LAYOUT_YC && r > ROLE_Y);
        if (e == NULL || !used)
            continue;
        int want = r >= ROLE_RY ? 2 : 1;
        if (e->pixel_type != EXR_PIXEL_HALF && e->pixel_type != EXR_PIXEL_FLOAT) {
            error_set(io->err,
                      "channel %s holds unsigned integers: colour channels must be "
                      "half or float",
                      e->name.str);
            return false;
        }
        if (e->x_sampling != want || e->y_sampling != want) {
            error_set(io->err, "channel %s is sampled %d x %d: raytra reads it sampled %d x %d",
                      e->name.str, e->x_sampling, e->y_sampling, want, want);
            return false;
        }
        plan->sampling[r] = want;
    }
    return true;
}

/* Finds the luminance weights of R, G and B from the part's chromaticities (Rec. 709 when
 * it has none) as OpenEXR's computeYw does, in the same float operations: the Y row of the
 * RGB-to-XYZ matrix, normalised to sum 1. False (in io) for degenerate chromaticities. */
static bool luminance_weights(exr_context_t ctxt, float yw[3], ExrIo *io)
{
    exr_attr_chromaticities_t c = {0.6400f, 0.3300f, 0.3000f, 0.6000f,
                                   0.1500f, 0.0600f, 0.3127f, 0.3290f};
    const exr_attribute_t *attr = NULL;
    if (exr_get_attribute_by_name(ctxt, 0, "chromaticities", &attr) == EXR_ERR_SUCCESS &&
        attr != NULL && attr->type == EXR_ATTR_CHROMATICITIES)
        c = *attr->chromaticities;
    const float Y = 1;
    /* X and Z of white, the RGB value (1, 1, 1). */
    if (fabsf(c.white_y) <= 1.f && fabsf(c.white_x * Y) >= fabsf(c.white_y) * FLT_MAX) {
        error_set(io->err, "its chromaticities are degenerate (white y is 0)");
        return false;
    }
    float X = c.white_x * Y / c.white_y;
    float Z = (1 - c.white_x - c.white_y) * Y / c.white_y;
    /* The scale of each primary's row: numerators over a common denominator. */
    float d = c.red_x * (c.blue_y - c.green_y) + c.blue_x * (c.green_y - c.red_y) +
              c.green_x * (c.red_y - c.blue_y);
    float sr = (X * (c.blue_y - c.green_y) - c.green_x * (Y * (c.blue_y - 1) + c.blue_y * (X + Z)) +
                c.blue_x * (Y * (c.green_y - 1) + c.green_y * (X + Z)));
    float sg = (X * (c.red_y - c.blue_y) + c.red_x * (Y * (c.blue_y - 1) + c.blue_y * (X + Z)) -
                c.blue_x * (Y * (c.red_y - 1) + c.red_y * (X + Z)));
    float sb = (X * (c.green_y - c.red_y) - c.red_x * (Y * (c.green_y - 1) + c.green_y * (X + Z)) +
                c.green_x * (Y * (c.red_y - 1) + c.red_y * (X + Z)));
    if (fabsf(d) < 1.f && (fabsf(sr) >= fabsf(d) * FLT_MAX || fabsf(sg) >= fabsf(d) * FLT_MAX ||
                           fabsf(sb) >= fabsf(d) * FLT_MAX)) {
        error_set(io->err, "its chromaticities are degenerate (collinear primaries)");
        return false;
    }
    float m01 = sr / d * c.red_y, m11 = sg / d * c.green_y, m21 = sb / d * c.blue_y;
    float sum = m01 + m11 + m21;
    yw[0] = m01 / sum;
    yw[1] = m11 / sum;
    yw[2] = m21 / sum;
    return true;
}

/* Opens an OpenEXR context on the stream in io and checks what raytra needs of its header:
 * a single part of scanlines or tiles, its size within the limits, channels of a layout
 * it reads (in plan). False (in io) otherwise; *ctxt is then to be finished still. */
static bool open_header(exr_context_t *ctxt, const char *name, ExrIo *io, ExrPlan *plan)
{
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = on_error;
    init.user_data = io;
    init.read_fn = read_bytes;
    init.size_fn = query_size;
    init.alloc_fn = alloc_zeroed;
    init.free_fn = free;
    init.max_image_width = IMAGE_MAX_SIDE;
    init.max_image_height = IMAGE_MAX_SIDE;
    init.max_tile_width = IMAGE_MAX_SIDE;
    init.max_tile_height = IMAGE_MAX_SIDE;
    init.flags = EXR_CONTEXT_FLAG_SILENT_HEADER_PARSE;
    if (fseeko(io->in, 0, SEEK_END) != 0 || (io->size = ftello(io->in)) < 0) {
        error_set(io->err, "%s", strerror(errno));
        return false;
    }
    int parts = 0;
    exr_storage_t storage;
    exr_attr_box2i_t window;
    const exr_attr_chlist_t *list;
    if (failed(io, exr_start_read(ctxt, name, &init)) || failed(io, exr_get_count(*ctxt, &parts)))
        return false;
    if (parts != 1) {
        error_set(io->err, "it has %d parts: raytra reads single-part images only", parts);
        return false;
    }
    if (failed(io, exr_get_storage(*ctxt, 0, &storage)) ||
        failed(io, exr_get_data_window(*ctxt, 0, &window)) ||
        failed(io, exr_get_channels(*ctxt, 0, &list)))
        return false;
    if (storage != EXR_STORAGE_SCANLINE && storage != EXR_STORAGE_TILED) {
        error_set(io->err, "deep OpenEXR images cannot be read, only scanline and tiled ones");
        return false;
    }
    long width = (long)window.max.x - window.min.x + 1;
    long height = (long)window.max.y - window.min.y + 1;
    if (!image_size_ok(width, height)) {
        error_set(io->err,
                  "the image is %ld x %ld pixels: outside the limits (1 to %d a side, at most "
                  "%ld pixels)",
                  width, height, IMAGE_MAX_SIDE, IMAGE_MAX_PIXELS);
        return false;
    }
    *plan = (ExrPlan){.x0 = window.min.x,
                      .y0 = window.min.y,
                      .width = (int)width,
                      .height = (int)height,
                      .tiled = storage == EXR_STORAGE_TILED};
    if (!choose_layout(list, plan, io))
        return false;
    if (plan->layout == LAYOUT_YC &&
        (plan->x0 % 2 != 0 || plan->y0 % 2 != 0 || plan->width % 2 != 0 || plan->height % 2 != 0)) {
        error_set(io->err, "its data window does not hold whole 2 x 2 chroma samples");
        return false;
    }
    return plan->layout != LAYOUT_YC || luminance_weights(*ctxt, plan->yw, io);
}

/* Reads the size of the OpenEXR image in f from its header, parsed by the library (a
 * header may be of any length), and checks that raytra can read the image; false (err)
 * otherwise. */
bool image_exr_size(FILE *f, int *width, int *height, Error *err)
{
    ExrIo io = {.fd = -1, .in = f, .err = err};
    exr_context_t ctxt = NULL;
    ExrPlan plan;
    bool ok = open_header(&ctxt, "image", &io, &plan);
    if (ctxt != NULL)
        exr_finish(&ctxt);
    if (ok) {
        *width = plan.width;
        *height = plan.height;
    }
    return ok;
}

/* Names a chunk in messages: "lines 16 to 31", "tile (2, 0)". */
static void chunk_name(const exr_chunk_info_t *chunk, bool tiled, char *text, size_t size)
{
    if (tiled)
        snprintf(text, size, "tile (%d, %d)", chunk->start_x, chunk->start_y);
    else
        snprintf(text, size, "the chunk of lines %d to %d", chunk->start_y,
                 chunk->start_y + chunk->height - 1);
}

/* Tells whether line y holds samples of a channel sampled every ys lines. */
static bool line_sampled(int y, int ys)
{
    return ys <= 1 || y % ys == 0;
}

/* Checks, before a chunk is decoded, that its bytes are what its lines need: its packed
 * size is not zero, an uncompressed chunk holds exactly its lines, and the library's idea of
 * each channel's lines and of the chunk's size agrees with the lines sampled; every sample
 * then comes from bytes the decoder wrote. False (in io) otherwise. */
static bool check_chunk(const exr_decode_pipeline_t *d, const ExrPlan *plan, int ox, int oy,
                        ExrIo *io)
{
    const exr_chunk_info_t *ck = &d->chunk;
    char name[64];
    chunk_name(ck, plan->tiled, name, sizeof name);
    uint64_t need = 0;
    for (int c = 0; c < d->channel_count; c++) {
        const exr_coding_channel_info_t *ch = &d->channels[c];
        int lines = 0;
        for (int y = oy; y < oy + ck->height; y++)
            lines += line_sampled(y, ch->y_samples);
        if (lines != ch->height || ch->x_samples < 1 ||
            (int64_t)ch->width * ch->x_samples != ck->width) {
            char channel[32];
            printable_name(ch->channel_name, channel, sizeof channel);
            error_set(io->err, "%s does not hold whole samples of channel %s (sampled %d x %d)",
                      name, channel, ch->x_samples, ch->y_samples);
            return false;
        }
        need += (uint64_t)lines * (uint64_t)ch->width * (uint64_t)ch->bytes_per_element;
    }
    if (need != ck->unpacked_size || ck->packed_size == 0 ||
        (ck->compression == EXR_COMPRESSION_NONE && ck->packed_size != need)) {
        error_set(io->err, "%s holds %llu bytes, its lines need %llu%s", name,
                  (unsigned long long)ck->packed_size, (unsigned long long)need,
                  ck->compression == EXR_COMPRESSION_NONE ? " (uncompressed)" : "");
        return false;
    }
    if (ox < plan->x0 || oy < plan->y0 || ck->width < 1 || ck->height < 1 ||
        (int64_t)ox - plan->x0 + ck->width > plan->width ||
        (int64_t)oy - plan->y0 + ck->height > plan->height) {
        error_set(io->err, "%s lies outside the data window", name);
        return false;
    }
    return true;
}

/* Converts the decoded bytes of a chunk (lines one after the other, each the samples of
 * every channel in turn, little-endian) into the planes of the roles read. */
static void unpack_chunk(const exr_decode_pipeline_t *d, const ExrPlan *plan, int ox, int oy)
{
    const exr_chunk_info_t *ck = &d->chunk;
    const uint8_t *src = d->unpacked_buffer;
    for (int y = oy; y < oy + ck->height; y++)
        for (int c = 0; c < d->channel_count; c++) {
            const exr_coding_channel_info_t *ch = &d->channels[c];
            if (!line_sampled(y, ch->y_samples))
                continue;
            size_t bytes = (size_t)ch->width * ch->bytes_per_element;
            Role r = role_of(ch->channel_name);
            float *plane = r != ROLE_NONE ? plan->plane[r] : NULL;
            if (plane != NULL) {
                int s = plan->sampling[r];
                float *out = plane + (long)((y - plan->y0) / s) * plan->stride[r] +
                             (long)((ox - plan->x0) / s) * plan->step[r];
                for (int x = 0; x < ch->width; x++, out += plan->step[r]) {
                    const uint8_t *p = src + (size_t)x * ch->bytes_per_element;
                    float v;
                    if (ch->data_type == EXR_PIXEL_HALF) {
                        v = half_to_float((uint16_t)(p[0] | p[1] << 8));
                    } else {
                        uint32_t bits = (uint32_t)p[0] | (uint32_t)p[1] << 8 |
                                        (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
                        memcpy(&v, &bits, sizeof v);
                    }
                    /* RgbaInputFile reads luminance and chroma as halves. */
                    *out = plan->layout == LAYOUT_YC ? half_round(v) : v;
                }
            }
            src += bytes;
        }
}

/* Decodes one chunk, its top-left pixel at (ox, oy), into the planes with the decoder (set up by
 * the first chunk, *started then set); false (in io) on failure. The library only reads and
 * decompresses: raytra checks the chunk and unpacks its bytes itself. */
static bool decode_chunk(exr_context_t ctxt, const exr_chunk_info_t *chunk, const ExrPlan *plan,
                         int ox, int oy, exr_decode_pipeline_t *decoder, bool *started, ExrIo *io)
{
    if (!*started) {
        if (failed(io, exr_decoding_initialize(ctxt, 0, chunk, decoder)))
            return false;
        *started = true;
        /* No channel has a destination: the library's routines stop at the bytes. */
        if (failed(io, exr_decoding_choose_default_routines(ctxt, 0, decoder)))
            return false;
        decoder->unpack_and_convert_fn = NULL;
    } else if (failed(io, exr_decoding_update(ctxt, 0, chunk, decoder))) {
        return false;
    }
    if (!check_chunk(decoder, plan, ox, oy, io) || failed(io, exr_decoding_run(ctxt, 0, decoder)))
        return false;
    unpack_chunk(decoder, plan, ox, oy);
    return true;
}

/* Decodes every chunk of part 0 into the planes: blocks of scanlines, or the tiles of the
 * full-resolution level (mipmap levels below it are not read). */
static bool read_chunks(exr_context_t ctxt, const ExrPlan *plan, ExrIo *io)
{
    exr_decode_pipeline_t decoder = EXR_DECODE_PIPELINE_INITIALIZER;
    bool started = false, ok = true;
    if (!plan->tiled) {
        int32_t lines;
        ok = !failed(io, exr_get_scanlines_per_chunk(ctxt, 0, &lines));
        if (ok && lines < 1) {
            error_set(io->err, "%d lines a chunk", lines);
            ok = false;
        }
        for (long y = 0; ok && y < plan->height; y += lines) {
            exr_chunk_info_t chunk;
            ok = !failed(io, exr_read_scanline_chunk_info(ctxt, 0, plan->y0 + (int)y, &chunk)) &&
                 decode_chunk(ctxt, &chunk, plan, chunk.start_x, chunk.start_y, &decoder, &started,
                              io);
        }
    } else {
        int32_t tile_w, tile_h;
        ok = !failed(io, exr_get_tile_sizes(ctxt, 0, 0, 0, &tile_w, &tile_h));
        if (ok && (tile_w < 1 || tile_h < 1)) {
            error_set(io->err, "tiles of %d x %d pixels", tile_w, tile_h);
            ok = false;
        }
        for (long ty = 0; ok && ty * tile_h < plan->height; ty++)
            for (long tx = 0; ok && tx * tile_w < plan->width; tx++) {
                exr_chunk_info_t chunk;
                ok = !failed(io,
                             exr_read_tile_chunk_info(ctxt, 0, (int)tx, (int)ty, 0, 0, &chunk)) &&
                     decode_chunk(ctxt, &chunk, plan, plan->x0 + (int)(tx * tile_w),
                                  plan->y0 + (int)(ty * tile_h), &decoder, &started, io);
            }
    }
    if (started)
        exr_decoding_destroy(ctxt, &decoder);
    return ok;
}

/* The taps of OpenEXR's chroma reconstruction filter (ImfRgbaYca): a missing sample is
 * the weighted sum of the 14 known ones around it, 13 to 1 samples away on either side. */
static const float chroma_taps[14] = {0.002128f,  -0.007540f, 0.019597f,  -0.043159f, 0.087929f,
                                      -0.186077f, 0.627123f,  0.627123f,  -0.186077f, 0.087929f,
                                      -0.043159f, 0.019597f,  -0.007540f, 0.002128f};

/* Returns the row RgbaInputFile reads in place of row y of a height-row image: the first
 * above it, the last even one below it. */
static long clamp_row(long y, long height)
{
    return y < 0 ? 0 : y > height - 1 ? height - 2 : y;
}

/* Fills the chroma of every pixel of the even rows (width x height/2, from the samples at
 * even columns, sub): the samples themselves, and between them the filter over the samples
 * of the row, the first and the last standing for those beyond the edges. */
static void chroma_horizontal(const float *sub, int width, int height, float *full)
{
    for (long r = 0; r < height / 2; r++) {
        const float *in = sub + r * (width / 2);
        float *out = full + r * width;
        for (int x = 0; x < width; x++) {
            if (x % 2 == 0) {
                out[x] = in[x / 2];
                continue;
            }
            float sum = 0;
            for (int k = 0; k < 14; k++) {
                int at = x - 13 + 2 * k;
                at = at < 0 ? 0 : at > width - 1 ? width - 2 : at;
                float term = in[at / 2] * chroma_taps[k];
                sum = k == 0 ? term : sum + term;
            }
            out[x] = half_round(sum);
        }
    }
}

/* The RGB of one pixel from its luminance and chroma (YCAtoRGBA), as halves. */
static void yc_to_rgb(float y, float ry, float by, const float yw[3], float rgb[3])
{
    if (ry == 0 && by == 0) {
        rgb[0] = rgb[1] = rgb[2] = y;
        return;
    }
    float r = (ry + 1) * y, b = (by + 1) * y;
    float g = (y - r * yw[0] - b * yw[2]) / yw[1];
    rgb[0] = half_round(r);
    rgb[1] = half_round(g);
    rgb[2] = half_round(b);
}

/* Fills row y of rgb (width pixels; y may lie one row beyond the image) from luminance
 * and the horizontally filled chroma of the even rows: an even row's own chroma, an odd
 * row's filtered from the even rows above and below it. */
static void yc_row(const ExrPlan *plan, const float *luma, const float *ry, const float *by, long y,
                   float *rgb)
{
    int w = plan->width, h = plan->height;
    const float *lrow = luma + clamp_row(y, h) * w;
    for (int x = 0; x < w; x++) {
        float cr, cb;
        if (y % 2 == 0) {
            long at = clamp_row(y, h) / 2 * w + x;
            cr = ry[at];
            cb = by[at];
        } else {
            cr = cb = 0;
            for (int k = 0; k < 14; k++) {
                long at = clamp_row(y - 13 + 2 * k, h) / 2 * w + x;
                float tr = ry[at] * chroma_taps[k], tb = by[at] * chroma_taps[k];
                cr = k == 0 ? tr : cr + tr;
                cb = k == 0 ? tb : cb + tb;
            }
            cr = half_round(cr);
            cb = half_round(cb);
        }
        yc_to_rgb(lrow[x], cr, cb, plan->yw, rgb + 3 * x);
    }
}

/* std::max and std::min as OpenEXR uses them (NaN then compares as they do). */
static float max2(float a, float b)
{
    return a < b ? b : a;
}
static float min2(float a, float b)
{
    return b < a ? b : a;
}

/* The saturation of an RGB pixel: 1 - min / max, 0 when max is not positive. */
static float saturation(const float *p)
{
    float hi = max2(p[0], max2(p[1], p[2])), lo = min2(p[0], min2(p[1], p[2]));
    return hi > 0 ? 1 - lo / hi : 0;
}

/* Moves pixel in towards grey by f keeping its luminance (OpenEXR's desaturate). */
static void desaturate(const float *in, float f, const float yw[3], float *out)
{
    float hi = max2(in[0], max2(in[1], in[2]));
    for (int k = 0; k < 3; k++)
        out[k] = half_round(max2(hi - (hi - in[k]) * f, 0.0f));
    float y_in = in[0] * yw[0] + in[1] * yw[1] + in[2] * yw[2];
    float y_out = out[0] * yw[0] + out[1] * yw[1] + out[2] * yw[2];
    if (y_out > 0)
        for (int k = 0; k < 3; k++)
            out[k] = half_round(out[k] * (y_in / y_out));
}

/* Writes into out the pixels of row mid, each desaturated when it is much more saturated
 * than its four diagonal neighbours in rows above and below (OpenEXR's fixSaturation: the
 * chroma filter can overshoot at sharp colour edges). */
static void fix_saturation(const float *above, const float *mid, const float *below, int n,
                           const float yw[3], float *out)
{
    for (int i = 0; i < n; i++) {
        int left = i > 0 ? i - 1 : 0, right = i < n - 1 ? i + 1 : n - 1;
        float mean =
            min2(1.0f, 0.25f * (saturation(above + 3 * left) + saturation(above + 3 * right) +
                                saturation(below + 3 * left) + saturation(below + 3 * right)));
        const float *in = mid + 3 * i;
        float s = saturation(in);
        if (s > mean) {
            float s_max = min2(1.0f, 1 - (1 - mean) * 0.25f);
            if (s > s_max) {
                desaturate(in, s_max / s, yw, out + 3 * i);
                continue;
            }
        }
        memcpy(out + 3 * i, in, 3 * sizeof(float));
    }
}

/* Converts luminance and subsampled chroma into the RGB of img as OpenEXR's RgbaInputFile
 * does: chroma filled in along the rows, then down the columns, each pixel converted,
 * then overshooting saturation damped; every step rounded to halves as there. False when
 * out of memory. */
static bool yc_to_image(const ExrPlan *plan, Image *img)
{
    int w = plan->width, h = plan->height;
    float *ry = malloc(sizeof(float) * (size_t)w * (size_t)(h / 2));
    float *by = malloc(sizeof(float) * (size_t)w * (size_t)(h / 2));
    float *rows = malloc(sizeof(float) * 9 * (size_t)w);
    bool ok = ry != NULL && by != NULL && rows != NULL;
    if (ok) {
        chroma_horizontal(plan->plane[ROLE_RY], w, h, ry);
        chroma_horizontal(plan->plane[ROLE_BY], w, h, by);
        /* Three rows of RGB in turn: above, this one, below. */
        float *row[3] = {rows, rows + 3 * w, rows + 6 * w};
        yc_row(plan, plan->plane[ROLE_Y], ry, by, -1, row[0]);
        yc_row(plan, plan->plane[ROLE_Y], ry, by, 0, row[1]);
        for (long y = 0; y < h; y++) {
            yc_row(plan, plan->plane[ROLE_Y], ry, by, y + 1, row[2]);
            fix_saturation(row[0], row[1], row[2], w, plan->yw, img->pixels + 3 * y * w);
            float *oldest = row[0];
            row[0] = row[1];
            row[1] = row[2];
            row[2] = oldest;
        }
    }
    free(ry);
    free(by);
    free(rows);
    return ok;
}

/* Points the planes of the roles read at img, or at new planes for luminance and chroma;
 * false when out of memory. */
static bool make_planes(ExrPlan *plan, Image *img)
{
    long w = plan->width, h = plan->height;
    if (plan->layout != LAYOUT_YC) {
        for (int r = 0; r < ROLE_COUNT; r++)
            if (plan->sampling[r] > 0) {
                plan->plane[r] = img->pixels + (r == ROLE_Y ? 0 : r);
                plan->step[r] = 3;
                plan->stride[r] = 3 * w;
            }
        return true;
    }
    plan->plane[ROLE_Y] = malloc(sizeof(float) * (size_t)(w * h));
    plan->step[ROLE_Y] = 1;
    plan->stride[ROLE_Y] = w;
    /* Zeros stand for a chroma channel the file lacks, as in RgbaInputFile. */
    plan->plane[ROLE_RY] = calloc((size_t)(w / 2 * (h / 2)), sizeof(float));
    plan->plane[ROLE_BY] = calloc((size_t)(w / 2 * (h / 2)), sizeof(float));
    plan->sampling[ROLE_RY] = plan->sampling[ROLE_BY] = 2;
    for (int r = ROLE_RY; r <= ROLE_BY; r++) {
        plan->step[r] = 1;
        plan->stride[r] = w / 2;
    }
    return plan->plane[ROLE_Y] != NULL && plan->plane[ROLE_RY] != NULL &&
           plan->plane[ROLE_BY] != NULL;
}

/* Reads an OpenEXR image from the stream f (name, for the library's messages) into img
 * (overwritten; left empty on failure); see image_read_exr. */
bool image_read_exr_stream(Image *img, FILE *f, const char *name, Error *err)
{
    *img = (Image){0};
    ExrIo io = {.fd = -1, .in = f, .err = err};
    exr_context_t ctxt = NULL;
    ExrPlan plan = {0};
    bool ok = open_header(&ctxt, name, &io, &plan);
    if (ok && !image_init(img, plan.width, plan.height)) {
        error_set(err, "out of memory for a %d x %d image", plan.width, plan.height);
        ok = false;
    }
    if (ok && !make_planes(&plan, img)) {
        error_set(err, "out of memory for a %d x %d image", plan.width, plan.height);
        ok = false;
    }
    ok = ok && read_chunks(ctxt, &plan, &io);
    if (ok && plan.layout == LAYOUT_GREY)
        for (long k = 0; k < (long)img->width * img->height; k++)
            img->pixels[3 * k + 1] = img->pixels[3 * k + 2] = img->pixels[3 * k];
    if (ok && plan.layout == LAYOUT_YC && !yc_to_image(&plan, img)) {
        error_set(err, "out of memory for a %d x %d image", plan.width, plan.height);
        ok = false;
    }
    if (plan.layout == LAYOUT_YC)
        for (int r = ROLE_Y; r <= ROLE_BY; r++)
            free(plan.plane[r]);
    if (ctxt != NULL)
        exr_finish(&ctxt);
    if (!ok)
        image_free(img);
    return ok;
}

/* Reads the OpenEXR image at path into img (overwritten; left empty on failure): a single
 * part, scanline or tiled. R, G and B (other channels ignored; with a Y too, R, G and B are
 * read); Y alone as grey; luminance Y with chroma RY and BY sampled 2 x 2 (as OpenEXR's
 * RgbaOutputFile writes it) converted to RGB as OpenEXR's RgbaInputFile does. Half or float
 * samples, as floats; alpha is not applied, as OpenEXR colours are already multiplied by
 * it. Linear values, as the file holds them. Anything else is refused with a message. */
bool image_read_exr(Image *img, const char *path, Error *err)
{
    *img = (Image){0};
    FILE *f = fopen(path, "rb");
    if (f == NULL) {
        error_set(err, "%s", strerror(errno));
        return false;
    }
    bool ok = image_read_exr_stream(img, f, path, err);
    fclose(f);
    return ok;
}
