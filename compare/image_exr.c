/* image_exr.c: reading OpenEXR images: raytra's own reader where zlib decompresses the file,
 * OpenEXR's RGBA interface (exr_rgba.c) for the other layouts and compressions. */
#include "image_read.h"

#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "exr_read.h"
#include "exr_rgba.h"

/* The channel roles raytra knows; a channel of another name is not read. */
typedef enum { ROLE_R, ROLE_G, ROLE_B, ROLE_Y, ROLE_RY, ROLE_BY, ROLE_COUNT, ROLE_NONE } Role;
static const char *const role_names[ROLE_COUNT] = {"R", "G", "B", "Y", "RY", "BY"};

/* The channel layouts raytra reads. */
typedef enum {
    LAYOUT_RGB,  /* R, G and B (any other channel ignored) */
    LAYOUT_GREY, /* Y alone, as grey */
    LAYOUT_YC    /* luminance Y and chroma RY, BY sampled 2 x 2 (OpenEXR's library reads it) */
} ExrLayout;

/* How a file is read: its layout, the channel of each role (-1 for none). */
typedef struct {
    ExrLayout layout;
    int channel[ROLE_COUNT];
    bool library; /* read through OpenEXR's library: raytra's reader cannot decode it */
} ExrPlan;

/* Returns the role of the channel called name. */
static Role role_of(const char *name)
{
    for (int r = 0; r < ROLE_COUNT; r++)
        if (strcmp(name, role_names[r]) == 0)
            return (Role)r;
    return ROLE_NONE;
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

/* Describes a header's channel names in text: "A, Z" (the first eight, then "..."). */
static void channel_names(const ExrHeader *h, char *text, size_t size)
{
    snprintf(text, size, "%s", h->channel_count == 0 ? "none" : "");
    for (int c = 0; c < h->channel_count && c <= 8; c++) {
        char name[32];
        printable_name(h->channels[c].name, name, sizeof name);
        size_t used = strlen(text);
        snprintf(text + used, size - used, "%s%s", c > 0 ? ", " : "", c < 8 ? name : "...");
    }
}

/* Chooses the layout from the channel names and checks that raytra can read the channels
 * it uses: half or float samples, R, G, B and Y at full resolution, RY and BY sampled
 * 2 x 2; false (in err) otherwise. Other channels are not read. */
static bool choose_layout(const ExrHeader *h, ExrPlan *plan, Error *err)
{
    for (int r = 0; r < ROLE_COUNT; r++)
        plan->channel[r] = -1;
    for (int c = 0; c < h->channel_count; c++) {
        Role r = role_of(h->channels[c].name);
        if (r != ROLE_NONE)
            plan->channel[r] = c;
    }
    const int *at = plan->channel;
    int rgb = (at[ROLE_R] >= 0) + (at[ROLE_G] >= 0) + (at[ROLE_B] >= 0);
    bool chroma = at[ROLE_RY] >= 0 || at[ROLE_BY] >= 0;
    char names[320];
    if (rgb == 3) {
        plan->layout = LAYOUT_RGB;
    } else if (rgb > 0) {
        channel_names(h, names, sizeof names);
        error_set(err, "it has some of R, G and B but not all three (its channels: %s)", names);
        return false;
    } else if (at[ROLE_Y] >= 0) {
        plan->layout = chroma ? LAYOUT_YC : LAYOUT_GREY;
    } else {
        channel_names(h, names, sizeof names);
        error_set(err, "%s (its channels: %s)",
                  chroma ? "chroma channels RY, BY without the luminance Y"
                         : "no R, G and B channels, nor a Y channel",
                  names);
        return false;
    }
    for (int r = 0; r < ROLE_COUNT; r++) {
        bool used = plan->layout == LAYOUT_RGB
                        ? r <= ROLE_B
                        : r == ROLE_Y || (plan->layout == LAYOUT_YC && r > ROLE_Y);
        if (at[r] < 0 || !used)
            continue;
        const ExrChannel *e = &h->channels[at[r]];
        int want = r >= ROLE_RY ? 2 : 1;
        if (e->type == EXR_UINT) {
            error_set(err, "channel %s holds unsigned integers: colour channels must be half or float",
                      e->name);
            return false;
        }
        if (e->x_sampling != want || e->y_sampling != want) {
            error_set(err, "channel %s is sampled %d x %d: raytra reads it sampled %d x %d", e->name,
                      e->x_sampling, e->y_sampling, want, want);
            return false;
        }
    }
    return true;
}

/* Checks the chromaticities the luminance of a YC file is weighed by (Rec. 709 when it has
 * none), as OpenEXR's computeYw would divide by them: white's y, and the determinant of
 * the primaries, not zero. False (in err) for degenerate ones. */
static bool chromaticities_ok(const ExrHeader *h, Error *err)
{
    float c[8] = {0.6400f, 0.3300f, 0.3000f, 0.6000f, 0.1500f, 0.0600f, 0.3127f, 0.3290f};
    uint32_t size;
    const unsigned char *v = exr_attribute(h, "chromaticities", "chromaticities", &size);
    for (int k = 0; v != NULL && size == 32 && k < 8; k++) {
        uint32_t bits = exr_le32(v + 4 * k);
        memcpy(&c[k], &bits, sizeof c[k]);
    }
    float red_x = c[0], red_y = c[1], green_x = c[2], green_y = c[3], blue_x = c[4], blue_y = c[5];
    float white_x = c[6], white_y = c[7];
    if (fabsf(white_y) <= 1.f && fabsf(white_x) >= fabsf(white_y) * FLT_MAX) {
        error_set(err, "its chromaticities are degenerate (white y is 0)");
        return false;
    }
    /* X and Z of white (Y = 1), then each primary's scale: numerators over d. */
    float X = white_x / white_y, Z = (1 - white_x - white_y) / white_y;
    float d = red_x * (blue_y - green_y) + blue_x * (green_y - red_y) + green_x * (red_y - blue_y);
    float sr = X * (blue_y - green_y) - green_x * ((blue_y - 1) + blue_y * (X + Z)) +
               blue_x * ((green_y - 1) + green_y * (X + Z));
    float sg = X * (red_y - blue_y) + red_x * ((blue_y - 1) + blue_y * (X + Z)) -
               blue_x * ((red_y - 1) + red_y * (X + Z));
    float sb = X * (green_y - red_y) - red_x * ((green_y - 1) + green_y * (X + Z)) +
               green_x * ((red_y - 1) + red_y * (X + Z));
    if (fabsf(d) < 1.f && (fabsf(sr) >= fabsf(d) * FLT_MAX || fabsf(sg) >= fabsf(d) * FLT_MAX ||
                           fabsf(sb) >= fabsf(d) * FLT_MAX)) {
        error_set(err, "its chromaticities are degenerate (collinear primaries)");
        return false;
    }
    return true;
}

/* Reads the header of f and checks what raytra needs of it: a single part of scanlines or
 * tiles, its size within the limits, channels of a layout it reads (in plan). False (in
 * err) otherwise; h is to be freed either way. */
static bool open_header(FILE *f, ExrHeader *h, ExrPlan *plan, Error *err)
{
    if (!exr_read_header(f, h, err))
        return false;
    if (h->parts != 1) {
        error_set(err, "it has %d parts: raytra reads single-part images only", h->parts);
        return false;
    }
    if (h->deep) {
        error_set(err, "deep OpenEXR images cannot be read, only scanline and tiled ones");
        return false;
    }
    if (!image_size_ok(h->width, h->height)) {
        error_set(err,
                  "the image is %ld x %ld pixels: outside the limits (1 to %d a side, at most "
                  "%ld pixels)",
                  h->width, h->height, IMAGE_MAX_SIDE, IMAGE_MAX_PIXELS);
        return false;
    }
    if (!choose_layout(h, plan, err))
        return false;
    if (plan->layout == LAYOUT_YC &&
        (h->x0 % 2 != 0 || h->y0 % 2 != 0 || h->width % 2 != 0 || h->height % 2 != 0)) {
        error_set(err, "its data window does not hold whole 2 x 2 chroma samples");
        return false;
    }
    if (plan->layout == LAYOUT_YC && !chromaticities_ok(h, err))
        return false;
    plan->library = plan->layout == LAYOUT_YC || !exr_decodes(h);
    /* OpenEXR's RGBA interface reads Y as grey, and chroma, wherever they are. */
    if (plan->library && plan->layout == LAYOUT_RGB &&
        (plan->channel[ROLE_Y] >= 0 || plan->channel[ROLE_RY] >= 0 || plan->channel[ROLE_BY] >= 0)) {
        error_set(err, "it has R, G and B with luminance or chroma channels, %s: raytra reads "
                       "those only as scanlines compressed with NONE, RLE, ZIPS or ZIP",
                  h->tiled ? "in tiles" : "with another compression");
        return false;
    }
    return true;
}

/* Reads the size of the OpenEXR image in f from its header and checks that raytra can
 * read the image; false (err) otherwise. */
bool image_exr_size(FILE *f, int *width, int *height, Error *err)
{
    ExrHeader h;
    ExrPlan plan;
    bool ok = open_header(f, &h, &plan, err);
    if (ok) {
        *width = (int)h.width;
        *height = (int)h.height;
    }
    exr_header_free(&h);
    return ok;
}

/* Reads the pixels of the file f (header h) that raytra's reader decodes into img. */
static bool read_own(FILE *f, const ExrHeader *h, const ExrPlan *plan, Image *img, Error *err)
{
    ExrTarget *targets = calloc((size_t)h->channel_count, sizeof *targets);
    if (targets == NULL) {
        error_set(err, "out of memory");
        return false;
    }
    if (plan->layout == LAYOUT_RGB)
        for (int r = ROLE_R; r <= ROLE_B; r++)
            targets[plan->channel[r]] = (ExrTarget){img->pixels + r, 3};
    else
        targets[plan->channel[ROLE_Y]] = (ExrTarget){img->pixels, 3};
    bool ok = exr_read_pixels(f, h, targets, err);
    free(targets);
    /* Grey: Y in red, copied to green and blue. */
    if (ok && plan->layout == LAYOUT_GREY)
        for (long k = 0; k < (long)img->width * img->height; k++)
            img->pixels[3 * k + 1] = img->pixels[3 * k + 2] = img->pixels[3 * k];
    return ok;
}

/* Reads an OpenEXR image from f (path, when not NULL, names the same file for OpenEXR's
 * library) into img (overwritten; left empty on failure). */
static bool read_exr(Image *img, FILE *f, const char *path, Error *err)
{
    *img = (Image){0};
    ExrHeader h;
    ExrPlan plan;
    bool ok = open_header(f, &h, &plan, err);
    if (ok && plan.library && path == NULL) {
        error_set(err, "its layout needs OpenEXR's library, which reads it only from a file");
        ok = false;
    }
    if (ok && !image_init(img, (int)h.width, (int)h.height)) {
        error_set(err, "out of memory for a %ld x %ld image", h.width, h.height);
        ok = false;
    }
    if (ok)
        ok = plan.library ? exr_rgba_read(path, img, err) : read_own(f, &h, &plan, img, err);
    exr_header_free(&h);
    if (!ok)
        image_free(img);
    return ok;
}

/* Reads an OpenEXR image from the stream f (name, for messages) into img with raytra's
 * own reader alone (the layouts OpenEXR's library reads are refused); see image_read_exr. */
bool image_read_exr_stream(Image *img, FILE *f, const char *name, Error *err)
{
    (void)name;
    return read_exr(img, f, NULL, err);
}

/* Reads the OpenEXR image at path into img (overwritten; left empty on failure): a single
 * part, scanline or tiled. R, G and B (other channels ignored; with a Y too, R, G and B are
 * read); Y alone as grey; luminance Y with chroma RY and BY sampled 2 x 2 (as OpenEXR's
 * RgbaOutputFile writes it) converted to RGB as OpenEXR's RgbaInputFile does. Half or float
 * samples, as floats; alpha is not applied, as OpenEXR colours are already multiplied by
 * it. Linear values, as the file holds them. Scanlines compressed with NONE, RLE, ZIPS or
 * ZIP (raytra's own output among them) are read by raytra, exactly; every other file by
 * OpenEXR's RgbaInputFile, as halves. Anything else is refused with a message. */
bool image_read_exr(Image *img, const char *path, Error *err)
{
    *img = (Image){0};
    FILE *f = fopen(path, "rb");
    if (f == NULL) {
        error_set(err, "%s", strerror(errno));
        return false;
    }
    bool ok = read_exr(img, f, path, err);
    fclose(f);
    return ok;
}
