/* test_image_exr.c: OpenEXR: exact round trips, files other tools write, broken files. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "exr_read.h"
#include "image.h"
#include "image_read.h"
#include "stop.h"
#include "testing.h"

/* Returns the contents of path (size in *size); to free. */
static unsigned char *slurp(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    ck_assert_msg(f != NULL, "cannot open %s", path);
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    rewind(f);
    unsigned char *data = malloc((size_t)n + 1);
    ck_assert_uint_eq(fread(data, 1, (size_t)n, f), (size_t)n);
    fclose(f);
    *size = (size_t)n;
    return data;
}

/* A 7 x 5 image of values a float holds but a half or an 8-bit PNG would not: a third, a
 * tiny subnormal, 1e30, negatives; and a smooth gradient for the PNG comparison. */
static Image float_test_image(void)
{
    Image img;
    ck_assert(image_init(&img, 7, 5));
    for (int y = 0; y < 5; y++)
        for (int x = 0; x < 7; x++)
            image_set(&img, x, y, color(x / 6.0, y / 4.0, (x + y) / 10.0));
    image_set(&img, 0, 0, color(1.0 / 3.0, 1e-40, 1e30));
    image_set(&img, 6, 4, color(-2.5, 70000.0, 0.1));
    return img;
}

START_TEST(exr_by_extension)
{
    ck_assert_int_eq(image_format_for_path("a.exr"), IMAGE_FORMAT_EXR);
    ck_assert_int_eq(image_format_for_path("out/A.EXR"), IMAGE_FORMAT_EXR);
    ck_assert_int_eq(image_format_for_path("x.exr.png"), IMAGE_FORMAT_PNG);
    Image img;
    ck_assert(image_init(&img, 1, 1));
    Error err;
    ck_assert(!image_write(&img, "out.jpg", PNG_ENCODING_SRGB, &err));
    ck_assert_str_eq(err.text, "unknown image format (use .png, .pfm or .exr)");
    image_free(&img);
}
END_TEST

START_TEST(exr_round_trip_is_exact)
{
    /* raytra writes 32-bit floats: every value comes back bit for bit. */
    Image img = float_test_image(), back;
    Error err;
    ck_assert_msg(image_write(&img, "t.exr", PNG_ENCODING_SRGB, &err), "%s", err.text);
    ck_assert_msg(image_read(&back, "t.exr", &err), "%s", err.text);
    ck_assert_int_eq(back.width, 7);
    ck_assert_int_eq(back.height, 5);
    ck_assert_mem_eq(back.pixels, img.pixels, sizeof(float) * 3 * 7 * 5);
    image_free(&back);
    /* The same values as the PFM of the image. */
    ck_assert(image_write(&img, "t.pfm", PNG_ENCODING_SRGB, &err));
    ck_assert(image_read(&back, "t.pfm", &err));
    ck_assert_mem_eq(back.pixels, img.pixels, sizeof(float) * 3 * 7 * 5);
    image_free(&back);
    image_free(&img);
}
END_TEST

/* See below. */
static void assert_reads_as_openexr(const char *name);
static void need_openexr_files(void);

START_TEST(exr_raytra_writes_openexr_reads)
{
    /* OpenEXR's own reader gets every float raytra wrote, bit for bit. */
    Image img = float_test_image();
    Error err;
    ck_assert(image_write(&img, "raytra.exr", PNG_ENCODING_SRGB, &err));
    char command[4096];
    snprintf(command, sizeof command, "'%s' --floats raytra.exr", EXR_WRITER);
    ck_assert_msg(system(command) == 0, "%s failed", command);
    assert_reads_as_openexr("raytra.exr");
    size_t size;
    unsigned char *expected = slurp("raytra.rgba", &size);
    for (long k = 0; k < 7 * 5; k++)
        ck_assert_mem_eq(expected + 8 + 16 * k, img.pixels + 3 * k, 12);
    free(expected);
    image_free(&img);
}
END_TEST

START_TEST(exr_stream_reads_only_what_raytra_decodes)
{
    /* The stream reader (the fuzzers') leaves PIZ and tiles to OpenEXR's library. */
    need_openexr_files();
    FILE *f = fopen("piz.exr", "rb");
    Image img;
    Error err;
    ck_assert(!image_read_exr_stream(&img, f, "piz.exr", &err));
    ck_assert_str_eq(err.text, "its layout needs OpenEXR's library, which reads it only from a file");
    ck_assert_ptr_null(img.pixels);
    fclose(f);
    f = fopen("half.exr", "rb");
    ck_assert_msg(image_read_exr_stream(&img, f, "half.exr", &err), "%s", err.text);
    fclose(f);
    image_free(&img);
}
END_TEST

START_TEST(png_from_exr_equals_png_from_the_render)
{
    Image img = float_test_image(), back;
    Error err;
    ck_assert(image_write(&img, "direct.png", PNG_ENCODING_SRGB, &err));
    ck_assert(image_write(&img, "t.exr", PNG_ENCODING_SRGB, &err));
    ck_assert(image_read(&back, "t.exr", &err));
    ck_assert(image_write(&back, "via-exr.png", PNG_ENCODING_SRGB, &err));
    size_t n1, n2;
    unsigned char *a = slurp("direct.png", &n1), *b = slurp("via-exr.png", &n2);
    ck_assert_uint_eq(n1, n2);
    ck_assert_mem_eq(a, b, n1);
    free(a);
    free(b);
    image_free(&back);
    image_free(&img);
}
END_TEST

/* Writes the files of exr_writer.cpp (OpenEXR's C++ API) into the working folder, once. */
static void need_openexr_files(void)
{
    if (access("rgba.exr", F_OK) == 0)
        return;
    char command[4096];
    snprintf(command, sizeof command, "'%s' .", EXR_WRITER);
    ck_assert_msg(system(command) == 0, "%s failed", command);
}

/* The half nearest to 0.1 is 0x2e66: exponent 11 - 15 = -4, significand 1 + 614/1024, so
 * 1.599609375 / 16 = 0.0999755859375 (0.1 itself lies between it and the next half up,
 * 0.10009765625, nearer to it). */
#define HALF_0_1 0.0999755859375f

/* Asserts that img holds value()'s colours, with blue as b. */
static void assert_rgb(const Image *img, int width, int height, float b)
{
    ck_assert_int_eq(img->width, width);
    ck_assert_int_eq(img->height, height);
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            Color c = image_get(img, x, y);
            ck_assert_msg(c.r == x * 0.25f && c.g == y * 0.5f && c.b == b,
                          "pixel (%d, %d) is (%g, %g, %g)", x, y, c.r, c.g, c.b);
        }
}

START_TEST(exr_from_the_library_half_rgba_zip)
{
    /* 40 rows: several chunks of 16 rows, the last one short. Alpha is not applied. */
    need_openexr_files();
    Image img;
    Error err;
    ck_assert_msg(image_read(&img, "half.exr", &err), "%s", err.text);
    assert_rgb(&img, 9, 40, HALF_0_1);
    image_free(&img);
}
END_TEST

START_TEST(exr_from_the_library_half_piz_and_float_none)
{
    need_openexr_files();
    Image img;
    Error err;
    ck_assert_msg(image_read(&img, "piz.exr", &err), "%s", err.text);
    assert_rgb(&img, 33, 70, HALF_0_1);
    image_free(&img);
    /* Floats, no compression, a data window that does not start at (0, 0); RLE, ZIPS. */
    ck_assert_msg(image_read(&img, "float.exr", &err), "%s", err.text);
    assert_rgb(&img, 5, 3, 0.1f);
    image_free(&img);
    ck_assert_msg(image_read(&img, "rle.exr", &err), "%s", err.text);
    assert_rgb(&img, 7, 70, 0.1f);
    image_free(&img);
    ck_assert_msg(image_read(&img, "zips.exr", &err), "%s", err.text);
    assert_rgb(&img, 6, 5, HALF_0_1);
    image_free(&img);
}
END_TEST

START_TEST(exr_tiled_from_the_library)
{
    /* 37 x 21 pixels in tiles of 16: partial tiles at the right and the bottom; with the
     * data window away from the origin, and half and float samples. OpenEXR's RGBA
     * interface reads them: floats as halves. */
    need_openexr_files();
    Image img;
    Error err;
    ck_assert_msg(image_read(&img, "tiled.exr", &err), "%s", err.text);
    assert_rgb(&img, 37, 21, HALF_0_1);
    image_free(&img);
    ck_assert_msg(image_read(&img, "tiled-offset.exr", &err), "%s", err.text);
    assert_rgb(&img, 37, 21, HALF_0_1);
    image_free(&img);
}
END_TEST

START_TEST(exr_grey_is_read_as_rgb)
{
    need_openexr_files();
    Image img;
    Error err;
    ck_assert_msg(image_read(&img, "grey.exr", &err), "%s", err.text);
    for (int x = 0; x < 4; x++) {
        Color c = image_get(&img, x, 1);
        ck_assert(c.r == 0.75f + x && c.g == c.r && c.b == c.r);
    }
    image_free(&img);
}
END_TEST

START_TEST(exr_errors)
{
    Image img;
    Error err;
    /* No colour channels. */
    need_openexr_files();
    ck_assert(!image_read(&img, "alpha.exr", &err));
    ck_assert_str_eq(err.text, "no R, G and B channels, nor a Y channel (its channels: A)");
    ck_assert_ptr_null(img.pixels);
    /* A channel name that would be a terminal's control code is not printed as it is. */
    ck_assert(!image_read(&img, "escape.exr", &err));
    ck_assert_str_eq(err.text, "no R, G and B channels, nor a Y channel (its channels: ?)");
    /* Cut short: the header's end, then in the middle of the pixels. */
    Image good = float_test_image();
    ck_assert(image_write(&good, "good.exr", PNG_ENCODING_SRGB, &err));
    size_t size;
    unsigned char *data = slurp("good.exr", &size);
    size_t cuts[] = {4, 40, size / 2, size - 1};
    for (size_t k = 0; k < sizeof cuts / sizeof cuts[0]; k++) {
        FILE *f = fopen("cut.exr", "wb");
        fwrite(data, 1, cuts[k], f);
        fclose(f);
        ck_assert_msg(!image_read(&img, "cut.exr", &err), "a file cut at %zu bytes was read",
                      cuts[k]);
        ck_assert_ptr_null(img.pixels);
    }
    free(data);
    image_free(&good);
}
END_TEST

/* Returns the first place of the n bytes of what in data (size bytes), or NULL. */
static const unsigned char *find_bytes(const unsigned char *data, size_t size, const void *what,
                                       size_t n)
{
    for (size_t k = 0; k + n <= size; k++)
        if (memcmp(data + k, what, n) == 0)
            return data + k;
    return NULL;
}

/* Asserts that raytra reads the file name as OpenEXR does: the same size and the same R, G
 * and B, bit for bit, as name's .rgba (what RgbaInputFile, or InputFile, read of it). */
static void assert_reads_as_openexr(const char *name)
{
    char expected[256];
    snprintf(expected, sizeof expected, "%.*s.rgba", (int)strlen(name) - 4, name);
    size_t size;
    unsigned char *data = slurp(expected, &size);
    int32_t wh[2];
    ck_assert_uint_ge(size, sizeof wh);
    memcpy(wh, data, sizeof wh);
    ck_assert_uint_eq(size, sizeof wh + sizeof(float) * 4 * (size_t)wh[0] * (size_t)wh[1]);
    Image img;
    Error err;
    ck_assert_msg(image_read(&img, name, &err), "%s: %s", name, err.text);
    ck_assert_int_eq(img.width, wh[0]);
    ck_assert_int_eq(img.height, wh[1]);
    for (long k = 0; k < (long)wh[0] * wh[1]; k++)
        for (int c = 0; c < 3; c++) {
            float want;
            memcpy(&want, data + sizeof wh + sizeof(float) * (size_t)(4 * k + c), sizeof want);
            float got = img.pixels[3 * k + c];
            ck_assert_msg(memcmp(&got, &want, sizeof got) == 0,
                          "%s: pixel (%ld, %ld) channel %d is %.9g, OpenEXR reads %.9g", name,
                          k % wh[0], k / wh[0], c, got, want);
        }
    image_free(&img);
    free(data);
}

/* Asserts the above of every file of names (up to a NULL), which exr_writer writes. */
static void assert_read_as_openexr(const char *const *names)
{
    need_openexr_files();
    for (; *names != NULL; names++)
        assert_reads_as_openexr(*names);
}

START_TEST(exr_from_openexr_rgba_output_file)
{
    /* RgbaOutputFile's layouts: RGBA, in increasing and decreasing line order; luminance and chroma (the chroma sampled 2 x 2) with
     * and without alpha, default and Rec. 2020 chromaticities, compressed or not, the data
     * window away from the origin, decreasing lines, 2 x 2 pixels; luminance alone and with
     * alpha. RgbaInputFile's chroma filter and saturation fix are reproduced exactly. */
    assert_read_as_openexr((const char *const[]){"rgba.exr", "rgba-decreasing.exr", "yc.exr",
                                                 "yca.exr", "yc-rec2020.exr", "yc-tiny.exr",
                                                 "y.exr", "ya.exr", NULL});
}
END_TEST

START_TEST(exr_from_openexr_other_compressions)
{
    /* PXR24, B44, B44A, DWAA and DWAB through OpenEXR's library; ZIPS by raytra. */
    assert_read_as_openexr((const char *const[]){"rgba-pxr24.exr", "rgba-b44.exr", "yca-b44a.exr",
                                                 "yc-dwab.exr", "y-zips.exr", NULL});
    assert_reads_as_openexr("rgba-dwaa.exr");
}
END_TEST

START_TEST(exr_from_openexr_output_file)
{
    /* Grey with alpha and depth (once a crash in the library); many channels of all types
     * and samplings; R, G and B with a Y (R, G and B read); R, G and B with subsampled
     * channels raytra does not read, compressed and not; tiles with mipmap levels. */
    assert_read_as_openexr((const char *const[]){"yaz.exr", "many.exr", "rgby.exr", "rgb-sub.exr",
                                                 "rgb-sub-none.exr", "tiled-mipmap.exr", NULL});
}
END_TEST

START_TEST(exr_header_longer_than_4_kib)
{
    /* many.exr's header holds its channels and a long comment before the data window. */
    need_openexr_files();
    size_t size;
    unsigned char *data = slurp("many.exr", &size);
    const unsigned char *at = find_bytes(data, size, "dataWindow", 11);
    ck_assert_ptr_nonnull(at);
    ck_assert_int_gt(at - data, 4096);
    free(data);
    FILE *f = fopen("many.exr", "rb");
    int width = 0, height = 0;
    Error err;
    ck_assert_msg(image_exr_size(f, &width, &height, &err), "%s", err.text);
    fclose(f);
    ck_assert_int_eq(width, 40);
    ck_assert_int_eq(height, 24);
}
END_TEST

START_TEST(exr_layouts_refused)
{
    /* Files OpenEXR writes that raytra does not read: each refused, by the size check of
     * a header too, with what is wrong. */
    need_openexr_files();
    static const char *const cases[][2] = {
        {"two-parts.exr", "it has 2 parts: raytra reads single-part images only"},
        {"deep.exr", "deep OpenEXR images cannot be read, only scanline and tiled ones"},
        {"uint-y.exr", "channel Y holds unsigned integers: colour channels must be half or "
                       "float"},
        {"chroma-only.exr", "chroma channels RY, BY without the luminance Y (its channels: BY, "
                            "RY)"},
        {"rg.exr", "it has some of R, G and B but not all three (its channels: G, R)"},
        {"y-sub.exr", "channel Y is sampled 2 x 2: raytra reads it sampled 1 x 1"},
        {"yc-collinear.exr", "its chromaticities are degenerate (collinear primaries)"},
        {"rgby-piz.exr", "it has R, G and B with luminance or chroma channels, with another "
                         "compression: raytra reads those only as scanlines compressed with "
                         "NONE, RLE, ZIPS or ZIP"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        Image img;
        Error err;
        ck_assert_msg(!image_read(&img, cases[k][0], &err), "%s was read", cases[k][0]);
        ck_assert_str_eq(err.text, cases[k][1]);
        ck_assert_ptr_null(img.pixels);
        FILE *f = fopen(cases[k][0], "rb");
        int width, height;
        ck_assert(!image_exr_size(f, &width, &height, &err));
        ck_assert_str_eq(err.text, cases[k][1]);
        fclose(f);
    }
}
END_TEST

/* Where the chunk of the k-th block of lines of the single-part scanline file at path (data,
 * size bytes) is: the offset of its entry in the offset table, after the header (*entry),
 * and of its leader (returned). */
static size_t find_chunk(const char *path, const unsigned char *data, size_t size, int k,
                         size_t *entry)
{
    FILE *f = fopen(path, "rb");
    ExrHeader h;
    Error err;
    ck_assert_msg(exr_read_header(f, &h, &err), "%s", err.text);
    fclose(f);
    *entry = (size_t)h.table + 8 * (size_t)k;
    exr_header_free(&h);
    ck_assert_uint_le(*entry + 8, size);
    return (size_t)exr_le32(data + *entry) | (size_t)exr_le32(data + *entry + 4) << 32;
}

/* Stores the little-endian 32-bit v at p. */
static void put32(unsigned char *p, uint32_t v)
{
    for (int b = 0; b < 4; b++)
        p[b] = (unsigned char)(v >> (8 * b));
}

/* Writes size bytes of data to patched.exr, with the 4 bytes at offset at replaced by v
 * (none when at is SIZE_MAX), and reads it: false when raytra refuses it (err then says why,
 * img is empty). */
static bool read_patched(const unsigned char *data, size_t size, size_t at, uint32_t v, Image *img,
                         Error *err)
{
    unsigned char *copy = malloc(size);
    memcpy(copy, data, size);
    if (at != SIZE_MAX)
        put32(copy + at, v);
    FILE *f = fopen("patched.exr", "wb");
    ck_assert_uint_eq(fwrite(copy, 1, size, f), size);
    fclose(f);
    free(copy);
    bool ok = image_read(img, "patched.exr", err);
    ck_assert(ok || img->pixels == NULL);
    return ok;
}

/* Asserts that raytra refuses data patched (see read_patched) with a message holding want. */
static void assert_patched_refused(const unsigned char *data, size_t size, size_t at, uint32_t v,
                                   const char *want)
{
    Image img;
    Error err;
    ck_assert_msg(!read_patched(data, size, at, v, &img, &err), "read with %u at %zu (%s)", v, at,
                  want);
    ck_assert_msg(strstr(err.text, want) != NULL, "message '%s' lacks '%s'", err.text, want);
}

/* Asserts that raytra refuses data patched (see read_patched), or reads it as the file
 * unpatched (the library rebuilds an offset table that does not hold). */
static void assert_patched_refused_or_right(const unsigned char *data, size_t size, size_t at,
                                            uint32_t v, const char *path)
{
    Image img, right;
    Error err;
    if (!read_patched(data, size, at, v, &img, &err)) {
        ck_assert_str_ne(err.text, "");
        return;
    }
    ck_assert(image_read(&right, path, &err));
    ck_assert_int_eq(img.width, right.width);
    ck_assert_int_eq(img.height, right.height);
    ck_assert_mem_eq(img.pixels, right.pixels, sizeof(float) * 3 * (size_t)img.width * img.height);
    image_free(&img);
    image_free(&right);
}

START_TEST(exr_broken_chunks_refused)
{
    /* Uncompressed floats, 5 x 3: one line a chunk, 60 bytes (R, G and B, 5 x 4 bytes). */
    need_openexr_files();
    size_t size;
    unsigned char *data = slurp("none.exr", &size);
    size_t entry0, entry1;
    size_t leader0 = find_chunk("none.exr", data, size, 0, &entry0);
    size_t leader1 = find_chunk("none.exr", data, size, 1, &entry1);
    /* A chunk shorter or longer than its lines, or empty, with the file otherwise whole. */
    assert_patched_refused(data, size, leader1 + 4, 30,
                           "the chunk of lines 1 to 1 holds 30 bytes, its lines need 60 "
                           "(uncompressed)");
    assert_patched_refused(data, size, leader1 + 4, 59, "holds 59 bytes, its lines need 60");
    assert_patched_refused(data, size, leader0 + 4, 0, "the chunk of lines 0 to 0 holds 0 bytes");
    assert_patched_refused(data, size, leader1 + 4, 0x7fffffff, "holds 2147483647 bytes");
    /* A chunk that says it holds other lines. */
    assert_patched_refused(data, size, leader1, 2, "the chunk of lines 1 to 1 is not where");
    /* Offsets that lie: beyond the file, into the header, at another chunk. */
    assert_patched_refused_or_right(data, size, entry1, (uint32_t)size + 100, "none.exr");
    assert_patched_refused_or_right(data, size, entry1, 12, "none.exr");
    assert_patched_refused_or_right(data, size, entry1, (uint32_t)leader0, "none.exr");
    /* Cut in the middle of the last chunk. */
    assert_patched_refused(data, size - 10, SIZE_MAX, 0, "");
    /* A data window of 40000 x 3 pixels. */
    const unsigned char *dw = find_bytes(data, size, "dataWindow\0box2i", 17);
    ck_assert_ptr_nonnull(dw);
    size_t max_x = (size_t)(dw - data) + 17 + 4 + 8;
    assert_patched_refused(data, size, max_x, 39999, "");
    free(data);
    /* A compressed chunk whose size says less than it holds. */
    data = slurp("zip.exr", &size);
    leader0 = find_chunk("zip.exr", data, size, 0, &entry0);
    uint32_t packed = (uint32_t)data[leader0 + 4] | (uint32_t)data[leader0 + 5] << 8;
    assert_patched_refused(data, size, leader0 + 4, packed / 2, "");
    free(data);
    /* R, G and B with subsampled channels, uncompressed: a line with chroma (2) and one
     * without (3); 24 pixels of R, G and B and 12 of RY and BY, halves, and 6 floats of Z. */
    data = slurp("rgb-sub-none.exr", &size);
    leader0 = find_chunk("rgb-sub-none.exr", data, size, 0, &entry0);
    leader1 = find_chunk("rgb-sub-none.exr", data, size, 1, &entry1);
    assert_patched_refused(data, size, leader0 + 4, 144, "holds 144 bytes, its lines need 216");
    assert_patched_refused(data, size, leader1 + 4, 216, "holds 216 bytes, its lines need 144");
    assert_patched_refused_or_right(data, size, entry1, (uint32_t)leader0, "rgb-sub-none.exr");
    free(data);
}
END_TEST

START_TEST(exr_write_stops_when_asked)
{
    Image img = float_test_image();
    Error err;
    stop_request(2);
    ck_assert(!image_write(&img, "stopped.exr", PNG_ENCODING_SRGB, &err));
    stop_reset();
    ck_assert_str_eq(err.text, "interrupted");
    ck_assert_int_ne(access("stopped.exr", F_OK), 0);
    image_free(&img);
}
END_TEST

/* The OpenEXR tests. */
static Suite *exr_suite(void)
{
    Suite *s = suite_create("image_exr");
    TCase *tc = tcase_create("exr");
    tcase_add_test(tc, exr_by_extension);
    tcase_add_test(tc, exr_round_trip_is_exact);
    tcase_add_test(tc, exr_raytra_writes_openexr_reads);
    tcase_add_test(tc, exr_stream_reads_only_what_raytra_decodes);
    tcase_add_test(tc, png_from_exr_equals_png_from_the_render);
    tcase_add_test(tc, exr_from_the_library_half_rgba_zip);
    tcase_add_test(tc, exr_from_the_library_half_piz_and_float_none);
    tcase_add_test(tc, exr_tiled_from_the_library);
    tcase_add_test(tc, exr_grey_is_read_as_rgb);
    tcase_add_test(tc, exr_errors);
    tcase_add_test(tc, exr_from_openexr_rgba_output_file);
    tcase_add_test(tc, exr_from_openexr_other_compressions);
    tcase_add_test(tc, exr_from_openexr_output_file);
    tcase_add_test(tc, exr_header_longer_than_4_kib);
    tcase_add_test(tc, exr_layouts_refused);
    tcase_add_test(tc, exr_broken_chunks_refused);
    tcase_add_test(tc, exr_write_stops_when_asked);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(exr_suite)
