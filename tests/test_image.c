/* test_image.c: the image buffer, sRGB, PNG and PFM, against values worked out by hand. */
#include <png.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "image.h"
#include "image_read.h"
#include "stop.h"
#include "testing.h"

/* Asserts that a float is bit for bit the expected one (so -0 differs from 0). */
#define ck_assert_float_bits(a, b)                                                                 \
    do {                                                                                           \
        float a_ = (a), b_ = (b);                                                                  \
        ck_assert_msg(memcmp(&a_, &b_, sizeof a_) == 0, "expected %.9g, got %.9g", b_, a_);        \
    } while (0)

/* Asserts that pixel (x, y) of img holds exactly the colour (r, g, b) as floats. */
static void assert_pixel(const Image *img, int x, int y, float r, float g, float b)
{
    const float *p = img->pixels + 3 * (y * img->width + x);
    ck_assert_msg(p[0] == r && p[1] == g && p[2] == b,
                  "pixel (%d, %d): expected (%.9g, %.9g, %.9g), got (%.9g, %.9g, %.9g)", x, y, r, g,
                  b, p[0], p[1], p[2]);
}

/* Returns the float v / max, as the PNG reader computes it. */
static float frac(double v, double max)
{
    return (float)(v / max);
}

/* Writes size bytes to path. */
static void write_file(const char *path, const void *data, size_t size)
{
    FILE *f = fopen(path, "wb");
    ck_assert_ptr_nonnull(f);
    ck_assert_uint_eq(fwrite(data, 1, size, f), size);
    ck_assert_int_eq(fclose(f), 0);
}

/* Returns the contents of path (freed by the caller); *size is set to its length. */
static unsigned char *slurp(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    ck_assert_ptr_nonnull(f);
    unsigned char *data = malloc(1 << 20);
    ck_assert_ptr_nonnull(data);
    *size = fread(data, 1, 1 << 20, f);
    fclose(f);
    return data;
}

/* Asserts that reading path fails with a message containing expected, leaving img empty. */
static void assert_read_fails(const char *path, const char *expected)
{
    Image img;
    Error err = {""};
    ck_assert(!image_read(&img, path, &err));
    ck_assert_msg(strstr(err.text, expected) != NULL, "expected '%s' in '%s'", expected, err.text);
    ck_assert_ptr_null(img.pixels);
    ck_assert_int_eq(img.width, 0);
}

/* Asserts that the PFM made of header and then size bytes of data is refused with a
 * message containing expected. */
static void assert_pfm_fails(const char *header, size_t size, const char *expected)
{
    char data[256];
    size_t len = strlen(header);
    ck_assert_uint_le(len + size, sizeof data);
    memcpy(data, header, len);
    memset(data + len, 0, size);
    write_file("bad.pfm", data, len + size);
    assert_read_fails("bad.pfm", expected);
}

/* What a test PNG is made of, written by libpng directly (not by the code under test). */
typedef struct {
    int width, height, bit_depth, color_type;
    const unsigned char *rows; /* packed as PNG stores them: 16-bit samples big-endian */
    const png_color *palette;
    int palette_size;
    const png_byte *trans_alpha; /* tRNS of a palette image */
    int trans_count;
    const png_color_16 *trans_color; /* tRNS of a gray or RGB image */
    bool interlace;
} TestPng;

/* Writes t to path with libpng. */
static void write_test_png(const char *path, TestPng t)
{
    FILE *f = fopen(path, "wb");
    ck_assert_ptr_nonnull(f);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png_create_info_struct(png);
    ck_assert_ptr_nonnull(info);
    if (setjmp(png_jmpbuf(png)))
        ck_abort_msg("libpng could not write the test PNG");
    png_init_io(png, f);
    png_set_IHDR(png, info, (png_uint_32)t.width, (png_uint_32)t.height, t.bit_depth, t.color_type,
                 t.interlace ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (t.palette != NULL)
        png_set_PLTE(png, info, t.palette, t.palette_size);
    if (t.trans_alpha != NULL || t.trans_color != NULL)
        png_set_tRNS(png, info, t.trans_alpha, t.trans_count, t.trans_color);
    png_write_info(png, info);
    size_t stride = png_get_rowbytes(png, info);
    png_bytep rows[64];
    ck_assert_int_le(t.height, 64);
    for (int y = 0; y < t.height; y++)
        rows[y] = (png_bytep)t.rows + y * stride;
    png_write_image(png, rows);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    ck_assert_int_eq(fclose(f), 0);
}

/* Returns a test PNG of the given kind, without a palette or transparency. */
static TestPng test_png(int width, int height, int bit_depth, int color_type,
                        const unsigned char *rows)
{
    return (TestPng){.width = width,
                     .height = height,
                     .bit_depth = bit_depth,
                     .color_type = color_type,
                     .rows = rows};
}

/* What libpng itself finds in a PNG: the raw 8-bit samples and the colour chunks. */
typedef struct {
    int width, height, bit_depth, color_type;
    unsigned char bytes[64 * 3];
    bool has_srgb;
    double gamma; /* 0 when there is no gAMA chunk */
} RawPng;

/* Reads path with libpng, without any transformation. */
static RawPng read_raw_png(const char *path)
{
    RawPng raw;
    memset(&raw, 0, sizeof raw);
    FILE *f = fopen(path, "rb");
    ck_assert_ptr_nonnull(f);
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png_create_info_struct(png);
    ck_assert_ptr_nonnull(info);
    if (setjmp(png_jmpbuf(png)))
        ck_abort_msg("libpng could not read %s", path);
    png_init_io(png, f);
    png_read_png(png, info, PNG_TRANSFORM_IDENTITY, NULL);
    raw.width = (int)png_get_image_width(png, info);
    raw.height = (int)png_get_image_height(png, info);
    raw.bit_depth = png_get_bit_depth(png, info);
    raw.color_type = png_get_color_type(png, info);
    int intent;
    raw.has_srgb = png_get_sRGB(png, info, &intent) != 0;
    if (!png_get_gAMA(png, info, &raw.gamma))
        raw.gamma = 0;
    png_bytepp rows = png_get_rows(png, info);
    size_t stride = png_get_rowbytes(png, info);
    ck_assert_uint_le(stride * (size_t)raw.height, sizeof raw.bytes);
    for (int y = 0; y < raw.height; y++)
        memcpy(raw.bytes + y * stride, rows[y], stride);
    png_destroy_read_struct(&png, &info, NULL);
    fclose(f);
    return raw;
}

/* Reads path with image_read, asserting that it succeeds with the given size. */
static Image read_ok(const char *path, int width, int height)
{
    Image img;
    Error err = {""};
    ck_assert_msg(image_read(&img, path, &err), "reading %s: %s", path, err.text);
    ck_assert_int_eq(img.width, width);
    ck_assert_int_eq(img.height, height);
    return img;
}

/* Writes t to path with libpng and reads it back with image_read. */
static Image read_back(const char *path, TestPng t)
{
    write_test_png(path, t);
    return read_ok(path, t.width, t.height);
}

/* Writes size bytes to path, then reads them with image_read as a width x height image. */
static Image read_bytes(const char *path, const char *data, size_t size, int width, int height)
{
    write_file(path, data, size);
    return read_ok(path, width, height);
}

/* Writes img to path, asserting that it succeeds. */
static void write_ok(const Image *img, const char *path, PngEncoding encoding)
{
    Error err = {""};
    ck_assert_msg(image_write(img, path, encoding, &err), "writing %s: %s", path, err.text);
}

START_TEST(init_and_free)
{
    Image img;
    ck_assert(image_init(&img, 3, 2));
    ck_assert_int_eq(img.width, 3);
    ck_assert_int_eq(img.height, 2);
    for (int k = 0; k < 18; k++)
        ck_assert_float_eq(img.pixels[k], 0);
    image_set(&img, 2, 1, color(0.25, 0.5, 0.75));
    ck_assert_color_near(image_get(&img, 2, 1), color(0.25, 0.5, 0.75), 0);
    ck_assert_float_eq(img.pixels[3 * (1 * 3 + 2) + 1], 0.5f);
    image_free(&img);
    ck_assert_ptr_null(img.pixels);
    ck_assert_int_eq(img.width, 0);
    image_free(&img);
    Image zero = {0};
    image_free(&zero);
}
END_TEST

START_TEST(init_refuses_bad_sizes)
{
    Image img;
    ck_assert(!image_init(&img, 0, 5));
    ck_assert_ptr_null(img.pixels);
    ck_assert(!image_init(&img, 5, -1));
    ck_assert(!image_init(&img, IMAGE_MAX_SIDE + 1, 1));
    /* Both sides allowed, but 2^30 pixels is more than IMAGE_MAX_PIXELS (2^26). */
    ck_assert(!image_init(&img, IMAGE_MAX_SIDE, IMAGE_MAX_SIDE));
    ck_assert_int_eq(img.width, 0);
    ck_assert(image_init(&img, IMAGE_MAX_SIDE, 1));
    image_free(&img);
}
END_TEST

START_TEST(srgb_known_points)
{
    ck_assert_double_eq(image_srgb_encode(0), 0);
    ck_assert_double_eq_tol(image_srgb_encode(1), 1, 1e-15);
    /* 1.055 * 0.5^(1/2.4) - 0.055 = 1.055 * 0.7491535 - 0.055. */
    ck_assert_double_eq_tol(image_srgb_encode(0.5), 0.735356983, 1e-9);
    /* Below the boundary the curve is the straight line 12.92 c. */
    ck_assert_double_eq_tol(image_srgb_encode(0.001), 0.01292, 1e-15);
    ck_assert_double_eq_tol(image_srgb_encode(0.0031308), 0.040449936, 1e-15);
    ck_assert_double_eq(image_srgb_decode(0), 0);
    ck_assert_double_eq_tol(image_srgb_decode(1), 1, 1e-15);
    ck_assert_double_eq_tol(image_srgb_decode(0.735356983), 0.5, 1e-9);
    ck_assert_double_eq_tol(image_srgb_decode(0.01292), 0.001, 1e-15);
}
END_TEST

START_TEST(srgb_is_continuous_at_the_boundary)
{
    /* The standard's rounded constants make the two pieces meet to within 3e-8. */
    double below = image_srgb_encode(0.0031308);
    double above = image_srgb_encode(0.0031308 + 1e-12);
    ck_assert_double_eq_tol(below, above, 1e-7);
    ck_assert_double_eq_tol(image_srgb_decode(0.04045), image_srgb_decode(0.04045 + 1e-12), 1e-8);
    ck_assert_double_eq_tol(image_srgb_decode(0.04045), 0.0031308, 1e-8);
}
END_TEST

START_TEST(srgb_round_trip)
{
    double previous = -1;
    for (int k = 0; k <= 1000; k++) {
        double v = k / 1000.0;
        double e = image_srgb_encode(v);
        ck_assert_double_eq_tol(image_srgb_decode(e), v, 1e-12);
        ck_assert_double_gt(e, previous);
        previous = e;
    }
}
END_TEST

START_TEST(format_by_extension)
{
    ck_assert_int_eq(image_format_for_path("a.png"), IMAGE_FORMAT_PNG);
    ck_assert_int_eq(image_format_for_path("out/A.PNG"), IMAGE_FORMAT_PNG);
    ck_assert_int_eq(image_format_for_path("x.pfm"), IMAGE_FORMAT_PFM);
    ck_assert_int_eq(image_format_for_path("../x.Pfm"), IMAGE_FORMAT_PFM);
    ck_assert_int_eq(image_format_for_path("x"), IMAGE_FORMAT_UNKNOWN);
    ck_assert_int_eq(image_format_for_path("x.jpg"), IMAGE_FORMAT_UNKNOWN);
    ck_assert_int_eq(image_format_for_path("x.png.bak"), IMAGE_FORMAT_UNKNOWN);
    ck_assert_int_eq(image_format_for_path("dir.png/x"), IMAGE_FORMAT_UNKNOWN);
    ck_assert_int_eq(image_format_for_path(""), IMAGE_FORMAT_UNKNOWN);
}
END_TEST

START_TEST(write_unknown_format)
{
    Image img;
    ck_assert(image_init(&img, 1, 1));
    Error err = {""};
    ck_assert(!image_write(&img, "out.jpg", PNG_ENCODING_SRGB, &err));
    ck_assert_ptr_nonnull(strstr(err.text, "unknown image format"));
    ck_assert_ptr_null(fopen("out.jpg", "rb"));
    image_free(&img);
    Image empty = {0};
    ck_assert(!image_write(&empty, "out.png", PNG_ENCODING_SRGB, &err));
}
END_TEST

/* A 4 x 2 image: the top row tests the sRGB values, the bottom one clamping. */
static Image png_test_image(void)
{
    Image img;
    ck_assert(image_init(&img, 4, 2));
    image_set(&img, 0, 0, color(1, 0, 0));
    /* 0.5 -> 0.7353570 * 255 = 187.52 -> 188. 0.2159 -> 0.5020 * 255 = 128.01 -> 128.
     * 0.001 is on the straight piece: 12.92 * 0.001 * 255 = 3.29 -> 3. */
    image_set(&img, 1, 0, color(0.5, 0.2159, 0.001));
    /* 0.25 -> 0.5371 * 255 = 136.96 -> 137; 0.002 -> 0.02584 * 255 = 6.59 -> 7. */
    image_set(&img, 2, 0, color(0.25, 0.6, 0.002));
    image_set(&img, 3, 0, color(0, 1, 0));
    image_set(&img, 0, 1, color(0, 0, 1));
    image_set(&img, 1, 1, color(2.0, -1.0, NAN));
    image_set(&img, 2, 1, color(INFINITY, -INFINITY, 1e30));
    image_set(&img, 3, 1, color(1, 1, 1));
    return img;
}

START_TEST(png_srgb_values)
{
    Image img = png_test_image();
    write_ok(&img, "srgb.png", PNG_ENCODING_SRGB);
    RawPng raw = read_raw_png("srgb.png");
    ck_assert_int_eq(raw.width, 4);
    ck_assert_int_eq(raw.height, 2);
    ck_assert_int_eq(raw.bit_depth, 8);
    ck_assert_int_eq(raw.color_type, PNG_COLOR_TYPE_RGB);
    ck_assert(raw.has_srgb);
    /* 0.6 -> 0.7977 * 255 = 203.4 -> 203. */
    const unsigned char expected[] = {
        255, 0, 0,   188, 128, 3, 137, 203, 7,   0,   255, 0,   /* top row first */
        0,   0, 255, 255, 0,   0, 255, 0,   255, 255, 255, 255, /* clamped: >1, <0, NaN */
    };
    ck_assert_mem_eq(raw.bytes, expected, sizeof expected);
    image_free(&img);
}
END_TEST

START_TEST(png_linear_values)
{
    Image img = png_test_image();
    write_ok(&img, "linear.png", PNG_ENCODING_LINEAR);
    RawPng raw = read_raw_png("linear.png");
    ck_assert(!raw.has_srgb);
    ck_assert_double_eq_tol(raw.gamma, 1.0, 1e-5);
    /* round(255 v): 0.5 -> 128 (127.5 rounds up), 0.2159 -> 55.05 -> 55,
     * 0.001 -> 0.26 -> 0, 0.25 -> 63.75 -> 64, 0.6 -> 153, 0.002 -> 0.51 -> 1. */
    const unsigned char expected[] = {
        255, 0, 0,   128, 55, 0, 64,  153, 1,   0,   255, 0,
        0,   0, 255, 255, 0,  0, 255, 0,   255, 255, 255, 255,
    };
    ck_assert_mem_eq(raw.bytes, expected, sizeof expected);
    image_free(&img);
}
END_TEST

START_TEST(png_round_trip_reads_stored_values)
{
    Image img = png_test_image();
    write_ok(&img, "srgb.png", PNG_ENCODING_SRGB);
    Image back = read_ok("srgb.png", 4, 2);
    /* The reader gives the stored (encoded) values, not linear ones. */
    assert_pixel(&back, 0, 0, 1, 0, 0);
    assert_pixel(&back, 1, 0, frac(188, 255), frac(128, 255), frac(3, 255));
    assert_pixel(&back, 0, 1, 0, 0, 1);
    assert_pixel(&back, 1, 1, 1, 0, 0);
    image_free(&back);
    image_free(&img);
}
END_TEST

START_TEST(png_output_is_reproducible)
{
    Image img = png_test_image();
    write_ok(&img, "one.png", PNG_ENCODING_SRGB);
    write_ok(&img, "two.png", PNG_ENCODING_SRGB);
    size_t n1, n2;
    unsigned char *a = slurp("one.png", &n1), *b = slurp("two.png", &n2);
    ck_assert_uint_eq(n1, n2);
    ck_assert_mem_eq(a, b, n1);
    free(a);
    free(b);
    image_free(&img);
}
END_TEST

START_TEST(png_read_16_bit_rgb)
{
    /* 0x1234 = 4660 keeps its low byte: 4660 / 65535, not 0x12 / 255. */
    const unsigned char rows[] = {0x12, 0x34, 0xff, 0xff, 0x00, 0x01,
                                  0x80, 0x00, 0x00, 0x00, 0xff, 0xfe};
    Image img = read_back("rgb16.png", test_png(2, 1, 16, PNG_COLOR_TYPE_RGB, rows));
    assert_pixel(&img, 0, 0, frac(4660, 65535), 1, frac(1, 65535));
    assert_pixel(&img, 1, 0, frac(32768, 65535), 0, frac(65534, 65535));
    image_free(&img);
}
END_TEST

START_TEST(png_read_gray)
{
    const unsigned char rows[] = {0, 128, 255};
    Image img = read_back("gray.png", test_png(1, 3, 8, PNG_COLOR_TYPE_GRAY, rows));
    assert_pixel(&img, 0, 0, 0, 0, 0);
    assert_pixel(&img, 0, 1, frac(128, 255), frac(128, 255), frac(128, 255));
    assert_pixel(&img, 0, 2, 1, 1, 1);
    image_free(&img);
}
END_TEST

START_TEST(png_read_gray_1_bit)
{
    /* One byte holds the row's 3 pixels 1, 0, 1 from the high bit down: 101xxxxx. */
    const unsigned char rows[] = {0xa0};
    Image img = read_back("bits.png", test_png(3, 1, 1, PNG_COLOR_TYPE_GRAY, rows));
    assert_pixel(&img, 0, 0, 1, 1, 1);
    assert_pixel(&img, 1, 0, 0, 0, 0);
    assert_pixel(&img, 2, 0, 1, 1, 1);
    image_free(&img);
}
END_TEST

START_TEST(png_read_gray_alpha)
{
    /* Gray 200 at alpha 128, over black: 200/255 * 128/255. */
    const unsigned char rows[] = {200, 128, 200, 255, 200, 0};
    Image img = read_back("ga.png", test_png(3, 1, 8, PNG_COLOR_TYPE_GRAY_ALPHA, rows));
    float g = (float)(200.0 / 255 * (128.0 / 255));
    assert_pixel(&img, 0, 0, g, g, g);
    assert_pixel(&img, 1, 0, frac(200, 255), frac(200, 255), frac(200, 255));
    assert_pixel(&img, 2, 0, 0, 0, 0);
    image_free(&img);
}
END_TEST

START_TEST(png_read_rgba)
{
    /* Alpha 51/255 = 0.2 scales the colour (255, 100, 0) to (0.2, 100/255 * 0.2, 0). */
    const unsigned char rows[] = {255, 100, 0, 51, 10, 20, 30, 255};
    Image img = read_back("rgba.png", test_png(2, 1, 8, PNG_COLOR_TYPE_RGBA, rows));
    assert_pixel(&img, 0, 0, (float)(51.0 / 255), (float)(100.0 / 255 * (51.0 / 255)), 0);
    assert_pixel(&img, 1, 0, frac(10, 255), frac(20, 255), frac(30, 255));
    image_free(&img);
}
END_TEST

START_TEST(png_read_rgba_16_bit)
{
    const unsigned char rows[] = {0xff, 0xff, 0x80, 0x00, 0x00, 0x00, 0x80, 0x00};
    Image img = read_back("rgba16.png", test_png(1, 1, 16, PNG_COLOR_TYPE_RGBA, rows));
    double a = 32768.0 / 65535;
    assert_pixel(&img, 0, 0, (float)a, (float)(32768.0 / 65535 * a), 0);
    image_free(&img);
}
END_TEST

START_TEST(png_read_palette_with_transparency)
{
    const png_color palette[] = {{10, 20, 30}, {255, 0, 0}, {0, 0, 255}};
    const png_byte alpha[] = {255, 0}; /* entry 2 has no alpha given: opaque */
    const unsigned char rows[] = {0, 1, 2};
    TestPng t = test_png(3, 1, 8, PNG_COLOR_TYPE_PALETTE, rows);
    t.palette = palette;
    t.palette_size = 3;
    t.trans_alpha = alpha;
    t.trans_count = 2;
    Image img = read_back("pal.png", t);
    assert_pixel(&img, 0, 0, frac(10, 255), frac(20, 255), frac(30, 255));
    assert_pixel(&img, 1, 0, 0, 0, 0);
    assert_pixel(&img, 2, 0, 0, 0, 1);
    image_free(&img);
}
END_TEST

START_TEST(png_read_rgb_with_transparent_colour)
{
    /* tRNS names one colour fully transparent: that pixel composites to black. */
    const png_color_16 transparent = {.red = 1, .green = 2, .blue = 3};
    const unsigned char rows[] = {1, 2, 3, 1, 2, 4};
    TestPng t = test_png(2, 1, 8, PNG_COLOR_TYPE_RGB, rows);
    t.trans_color = &transparent;
    Image img = read_back("trns.png", t);
    assert_pixel(&img, 0, 0, 0, 0, 0);
    assert_pixel(&img, 1, 0, frac(1, 255), frac(2, 255), frac(4, 255));
    image_free(&img);
}
END_TEST

START_TEST(png_read_interlaced)
{
    /* Adam7 spreads the pixels of a 9 x 9 image over all seven passes. */
    unsigned char rows[9 * 9 * 3];
    for (int k = 0; k < 9 * 9 * 3; k++)
        rows[k] = (unsigned char)(k * 7);
    TestPng t = test_png(9, 9, 8, PNG_COLOR_TYPE_RGB, rows);
    t.interlace = true;
    Image img = read_back("adam7.png", t);
    for (int k = 0; k < 9 * 9 * 3; k++)
        ck_assert_float_eq(img.pixels[k], frac(rows[k], 255));
    image_free(&img);
}
END_TEST

START_TEST(png_read_errors)
{
    assert_read_fails("missing.png", "No such file");
    write_file("empty.png", "", 0);
    assert_read_fails("empty.png", "empty file");
    write_file("text.png", "hello, world\n", 13);
    assert_read_fails("text.png", "not a PNG, PFM or OpenEXR image");
    Image img;
    Error err = {""};
    ck_assert(!image_read_png(&img, "text.png", &err));
    ck_assert_str_eq(err.text, "not a PNG file");

    /* A valid PNG cut in the middle of its pixels. */
    Image big;
    ck_assert(image_init(&big, 40, 40));
    for (int k = 0; k < 40 * 40 * 3; k++)
        big.pixels[k] = (float)((k * 37) % 101) / 100;
    write_ok(&big, "whole.png", PNG_ENCODING_SRGB);
    size_t size;
    unsigned char *data = slurp("whole.png", &size);
    write_file("cut.png", data, size / 2);
    assert_read_fails("cut.png", "truncated");
    write_file("sig.png", data, 20);
    assert_read_fails("sig.png", "truncated");

    /* A damaged byte in the pixels: libpng's CRC check reports it. */
    data[size / 2] ^= 0x55;
    write_file("bad.png", data, size);
    ck_assert(!image_read(&img, "bad.png", &err));
    ck_assert_ptr_null(img.pixels);
    free(data);
    image_free(&big);
}
END_TEST

/* Writes a PNG signature and an IHDR that says width x height (the rest is never read). */
static void write_png_header(const char *path, uint32_t width, uint32_t height)
{
    unsigned char data[33] = {137, 'P', 'N', 'G', '\r', '\n', 26,  '\n',
                              0,   0,   0,   13,  'I',  'H',  'D', 'R'};
    for (int k = 0; k < 4; k++) {
        data[16 + k] = (unsigned char)(width >> (24 - 8 * k));
        data[20 + k] = (unsigned char)(height >> (24 - 8 * k));
    }
    data[24] = 8;
    data[25] = PNG_COLOR_TYPE_RGB;
    write_file(path, data, sizeof data);
}

START_TEST(png_read_refuses_huge_sizes)
{
    write_png_header("huge.png", 40000, 30);
    assert_read_fails("huge.png", "40000 x 30 pixels");
    /* Both sides within the limit, but 20000 * 20000 pixels is too many. */
    write_png_header("many.png", 20000, 20000);
    assert_read_fails("many.png", "20000 x 20000 pixels");
    write_png_header("zero.png", 0, 5);
    assert_read_fails("zero.png", "0 x 5 pixels");
    write_png_header("wrap.png", 0xffffffffu, 0xffffffffu);
    assert_read_fails("wrap.png", "4294967295 x 4294967295");
}
END_TEST

/* A 3 x 2 image of values that test a lossless format: signs, zeros, large and tiny. */
static Image pfm_test_image(void)
{
    Image img;
    ck_assert(image_init(&img, 3, 2));
    image_set(&img, 0, 0, color(0.1, -2.5, 1e30));
    image_set(&img, 1, 0, color(-0.0, 1e-40, 3.0e38));
    image_set(&img, 2, 0, color(INFINITY, 0.5, 1.0 / 3));
    image_set(&img, 0, 1, color(1, 0.5, -2));
    image_set(&img, 1, 1, color(0, 0, 0));
    image_set(&img, 2, 1, color(7, 8, 9));
    return img;
}

START_TEST(pfm_round_trip_is_exact)
{
    Image img = pfm_test_image();
    write_ok(&img, "exact.pfm", PNG_ENCODING_SRGB);
    Image back = read_ok("exact.pfm", 3, 2);
    for (int k = 0; k < 18; k++)
        ck_assert_float_bits(back.pixels[k], img.pixels[k]);
    image_free(&back);
    image_free(&img);
}
END_TEST

START_TEST(pfm_layout)
{
    Image img = pfm_test_image();
    write_ok(&img, "layout.pfm", PNG_ENCODING_SRGB);
    size_t size;
    unsigned char *data = slurp("layout.pfm", &size);
    const char header[] = "PF\n3 2\n-1.0\n";
    size_t h = sizeof header - 1;
    ck_assert_uint_eq(size, h + 3 * 2 * 3 * 4);
    ck_assert_mem_eq(data, header, h);
    /* The file's first row is the image's bottom row, (1, 0.5, -2) first, in
     * little-endian IEEE singles: 1 = 0x3f800000, 0.5 = 0x3f000000, -2 = 0xc0000000. */
    const unsigned char first[] = {0x00, 0x00, 0x80, 0x3f, 0x00, 0x00,
                                   0x00, 0x3f, 0x00, 0x00, 0x00, 0xc0};
    ck_assert_mem_eq(data + h, first, sizeof first);
    free(data);
    image_free(&img);
}
END_TEST

START_TEST(pfm_read_big_endian_and_gray)
{
    /* A positive scale means big-endian; its size (here 4) does not scale the values. */
    const char be[] = "PF\n1 1\n4.0\n\x3f\x80\x00\x00\xc0\x00\x00\x00\x3f\x00\x00\x00";
    Image img = read_bytes("be.pfm", be, sizeof be - 1, 1, 1);
    assert_pixel(&img, 0, 0, 1, -2, 0.5f);
    image_free(&img);
    /* Pf is gray: one float a pixel, copied to R, G and B; the bottom row comes first. */
    const char gray[] = "Pf\n1 2\n-1\n\x00\x00\x80\x3f\x00\x00\x00\x3f";
    img = read_bytes("gray.pfm", gray, sizeof gray - 1, 1, 2);
    assert_pixel(&img, 0, 0, 0.5f, 0.5f, 0.5f);
    assert_pixel(&img, 0, 1, 1, 1, 1);
    image_free(&img);
}
END_TEST

START_TEST(pfm_one_whitespace_after_scale)
{
    /* The second line break is the first byte of the data, not part of the header:
     * the first float's bytes are 0a 00 00 80, little-endian 0x8000000a. */
    const char data[] = "PF\n1 1\n-1.0\n\n\x00\x00\x80\x3f\x00\x00\x80\x3f\x00\x00\x80";
    Image img = read_bytes("ws.pfm", data, sizeof data - 1, 1, 1);
    uint32_t bits;
    memcpy(&bits, &img.pixels[0], sizeof bits);
    ck_assert_uint_eq(bits, 0x8000000a);
    image_free(&img);
}
END_TEST

START_TEST(pfm_malformed_headers)
{
    assert_pfm_fails("PX\n1 1\n-1\n", 12, "not a PNG, PFM or OpenEXR image");
    Image img;
    Error err = {""};
    write_file("px.pfm", "PX\n1 1\n-1\n", 10);
    ck_assert(!image_read_pfm(&img, "px.pfm", &err));
    ck_assert_ptr_nonnull(strstr(err.text, "not a PFM file"));
    assert_pfm_fails("PF1 1\n-1\n", 12, "not a PFM file");
    assert_pfm_fails("PF\nabc 1\n-1\n", 12, "width 'abc' is not a whole number");
    assert_pfm_fails("PF\n-3 1\n-1\n", 12, "width '-3' is not a whole number");
    assert_pfm_fails("PF\n+3 1\n-1\n", 12, "width '+3' is not a whole number");
    assert_pfm_fails("PF\n1 2.5\n-1\n", 12, "height '2.5' is not a whole number");
    assert_pfm_fails("PF\n0 1\n-1\n", 12, "0 x 1 pixels: outside the limits");
    assert_pfm_fails("PF\n40000 1\n-1\n", 12, "40000 x 1 pixels: outside the limits");
    assert_pfm_fails("PF\n99999999999999999999 1\n-1\n", 12, "99999999999999999999 x 1 pixels");
    assert_pfm_fails("PF\n1 1\n0\n", 12, "scale '0' is not a finite nonzero number");
    assert_pfm_fails("PF\n1 1\nnan\n", 12, "scale 'nan' is not a finite nonzero number");
    assert_pfm_fails("PF\n1 1\n-inf\n", 12, "scale '-inf' is not a finite nonzero number");
    assert_pfm_fails("PF\n1 1\n1e999\n", 12, "scale '1e999' is not a finite nonzero number");
    assert_pfm_fails("PF\n1 1\n-1x\n", 12, "scale '-1x' is not a finite nonzero number");
    assert_pfm_fails("PF\n1", 0, "the file ends within the width");
    assert_pfm_fails("PF\n1 ", 0, "the file ends before the height");
    assert_pfm_fails("PF\n1 1\n-1.0", 0, "the file ends within the scale");
    assert_pfm_fails("PF\n1 00000000000000000000000000000000000001\n-1\n", 12, "too long");
}
END_TEST

START_TEST(pfm_truncated_data)
{
    /* 2 x 1 RGB needs 24 bytes; there are 10. */
    assert_pfm_fails("PF\n2 1\n-1\n", 10, "truncated: expected 24 bytes of pixels, found 10");
    assert_pfm_fails("Pf\n2 2\n-1\n", 0, "truncated: expected 16 bytes of pixels, found 0");
}
END_TEST

START_TEST(read_dispatches_on_content)
{
    /* A PFM with a .png name is read as the PFM it is. */
    Image img = read_bytes("really.png", "Pf\n1 1\n-1\n\x00\x00\x80\x3e", 14, 1, 1);
    assert_pixel(&img, 0, 0, 0.25f, 0.25f, 0.25f);
    image_free(&img);
}
END_TEST

START_TEST(write_is_atomic)
{
    /* A failed write (here: interrupted) leaves the old file as it was and no temporary. */
    write_file("keep.png", "old contents", 12);
    Image img = png_test_image();
    Error err = {""};
    stop_request(2);
    ck_assert(!image_write(&img, "keep.png", PNG_ENCODING_SRGB, &err));
    stop_reset();
    ck_assert_str_eq(err.text, "interrupted");
    size_t size;
    unsigned char *data = slurp("keep.png", &size);
    ck_assert_uint_eq(size, 12);
    ck_assert_mem_eq(data, "old contents", 12);
    free(data);
    ck_assert(!image_write(&img, "nowhere/x.png", PNG_ENCODING_SRGB, &err));
    ck_assert_str_eq(err.text, "folder 'nowhere' does not exist");
    image_free(&img);
}
END_TEST

/* The image module's tests. */
static Suite *image_suite(void)
{
    Suite *s = suite_create("image");
    TCase *tc = tcase_create("buffer");
    tcase_add_test(tc, init_and_free);
    tcase_add_test(tc, init_refuses_bad_sizes);
    tcase_add_test(tc, srgb_known_points);
    tcase_add_test(tc, srgb_is_continuous_at_the_boundary);
    tcase_add_test(tc, srgb_round_trip);
    tcase_add_test(tc, format_by_extension);
    tcase_add_test(tc, write_unknown_format);
    suite_add_tcase(s, tc);
    tc = tcase_create("png");
    tcase_add_test(tc, png_srgb_values);
    tcase_add_test(tc, png_linear_values);
    tcase_add_test(tc, png_round_trip_reads_stored_values);
    tcase_add_test(tc, png_output_is_reproducible);
    tcase_add_test(tc, png_read_16_bit_rgb);
    tcase_add_test(tc, png_read_gray);
    tcase_add_test(tc, png_read_gray_1_bit);
    tcase_add_test(tc, png_read_gray_alpha);
    tcase_add_test(tc, png_read_rgba);
    tcase_add_test(tc, png_read_rgba_16_bit);
    tcase_add_test(tc, png_read_palette_with_transparency);
    tcase_add_test(tc, png_read_rgb_with_transparent_colour);
    tcase_add_test(tc, png_read_interlaced);
    tcase_add_test(tc, png_read_errors);
    tcase_add_test(tc, png_read_refuses_huge_sizes);
    suite_add_tcase(s, tc);
    tc = tcase_create("pfm");
    tcase_add_test(tc, pfm_round_trip_is_exact);
    tcase_add_test(tc, pfm_layout);
    tcase_add_test(tc, pfm_read_big_endian_and_gray);
    tcase_add_test(tc, pfm_one_whitespace_after_scale);
    tcase_add_test(tc, pfm_malformed_headers);
    tcase_add_test(tc, pfm_truncated_data);
    tcase_add_test(tc, read_dispatches_on_content);
    tcase_add_test(tc, write_is_atomic);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(image_suite)
