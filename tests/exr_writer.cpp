// exr_writer.cpp: writes OpenEXR test files with OpenEXR's own C++ API, and what it reads.
//
// Usage: exr_writer FOLDER
//        exr_writer --floats FILE.exr   write FILE.rgba: what InputFile reads of R, G and B
//
// Writes into FOLDER the files tests/test_image_exr.c reads with raytra's reader: the
// layouts other tools write (RgbaOutputFile's RGBA, luminance/chroma, luminance alone;
// OutputFile's many channels behind a long header, subsampled channels raytra does not use,
// R, G and B with a Y), and files raytra must refuse (several parts, deep data, integer
// colour). Beside each readable NAME.exr, NAME.rgba holds what OpenEXR reads of it: the
// width and height (two little-endian 32-bit integers), then R, G, B and A of every pixel
// as 32-bit floats, rows from the top. RgbaInputFile gives it, except for R, G and B with a
// Y, read as R, G and B by raytra (RgbaInputFile would read Y as grey): InputFile reads
// those channels.
#include <ImfArray.h>
#include <ImfChannelList.h>
#include <ImfDeepFrameBuffer.h>
#include <ImfDeepScanLineOutputFile.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfMultiPartOutputFile.h>
#include <ImfOutputFile.h>
#include <ImfOutputPart.h>
#include <ImfPartType.h>
#include <ImfRgbaFile.h>
#include <ImfStandardAttributes.h>
#include <ImfTiledOutputFile.h>
#include <ImfTiledRgbaFile.h>
#include <half.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

using namespace Imf;
using Imath::Box2i;
using Imath::V2f;
using Imath::V2i;

static std::string folder;

// Returns the path of file name in the output folder.
static std::string path(const std::string &name)
{
    return folder + "/" + name;
}

// The colour of pixel (x, y) of a w x h test image: smooth ramps, a saturated red square
// and blue and green bars with sharp edges (where the chroma filter overshoots), grey
// columns, a bright patch above 1 and a black corner.
static Rgba colour(int x, int y, int w, int h)
{
    float r = 0.2f + 0.8f * x / w, g = 0.1f + 0.6f * y / h, b = 0.3f + 0.2f * std::sin(0.7f * x);
    if (x >= w / 4 && x < w / 2 && y >= h / 4 && y < h / 2)
        r = 0.9f, g = 0.02f, b = 0.01f;
    if (x % 9 == 7)
        b = 3.0f, r = 0.05f;
    if (y % 7 == 5)
        g = 1.5f, b = 0.0f;
    if (x % 11 == 3)
        r = g = b = 0.25f + 0.01f * y;
    if (x > 3 * w / 4 && y > 3 * h / 4)
        r = 12.0f, g = 9.5f, b = 20.0f;
    if (x < 2 && y < 2)
        r = g = b = 0.0f;
    return Rgba(r, g, b, 0.5f + 0.5f * ((x + y) % 2));
}

// Fills pixels (w x h) with the test image.
static std::vector<Rgba> test_image(int w, int h)
{
    std::vector<Rgba> pixels((size_t)w * h);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            pixels[(size_t)y * w + x] = colour(x, y, w, h);
    return pixels;
}

// Writes w, h and the RGBA floats to NAME.rgba.
static void write_expected(const std::string &name, int w, int h, const std::vector<float> &rgba)
{
    std::string file = path(name.substr(0, name.size() - 4) + ".rgba");
    FILE *f = std::fopen(file.c_str(), "wb");
    if (f == nullptr)
        throw std::runtime_error("cannot write " + file);
    int32_t size[2] = {w, h};
    std::fwrite(size, sizeof size, 1, f);
    std::fwrite(rgba.data(), sizeof(float), rgba.size(), f);
    if (std::fclose(f) != 0)
        throw std::runtime_error("cannot write " + file);
}

// Reads the file with RgbaInputFile and writes what it gives as the expected values.
static void expect_rgba_input(const std::string &name)
{
    RgbaInputFile in(path(name).c_str());
    Box2i dw = in.dataWindow();
    int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
    Array2D<Rgba> pixels(h, w);
    in.setFrameBuffer(&pixels[0][0] - dw.min.x - (size_t)dw.min.y * w, 1, w);
    in.readPixels(dw.min.y, dw.max.y);
    std::vector<float> rgba;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            const Rgba &p = pixels[y][x];
            rgba.insert(rgba.end(), {float(p.r), float(p.g), float(p.b), float(p.a)});
        }
    write_expected(name, w, h, rgba);
}

// Reads R, G and B (and A, 1 when missing) with InputFile, as floats, as the expected values.
static void expect_channels(const std::string &name)
{
    InputFile in(path(name).c_str());
    Box2i dw = in.header().dataWindow();
    int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
    std::vector<float> rgba((size_t)w * h * 4);
    FrameBuffer fb;
    const char *names[4] = {"R", "G", "B", "A"};
    char *base = (char *)(rgba.data() - 4 * ((long)dw.min.x + (long)dw.min.y * w));
    for (int k = 0; k < 4; k++)
        fb.insert(names[k], Slice(FLOAT, base + k * sizeof(float), 4 * sizeof(float),
                                  4 * sizeof(float) * w, 1, 1, k == 3 ? 1.0 : 0.0));
    in.setFrameBuffer(fb);
    in.readPixels(dw.min.y, dw.max.y);
    write_expected(name, w, h, rgba);
}

// Writes the test image with RgbaOutputFile in the layout channels asks for.
static void write_rgba(const std::string &name, RgbaChannels channels, int w, int h, int x0, int y0,
                       Compression compression, LineOrder order = INCREASING_Y,
                       const Chromaticities *chromaticities = nullptr)
{
    Box2i dw(V2i(x0, y0), V2i(x0 + w - 1, y0 + h - 1));
    Header header(dw, dw, 1, V2f(0, 0), 1, order, compression);
    if (chromaticities != nullptr)
        addChromaticities(header, *chromaticities);
    RgbaOutputFile out(path(name).c_str(), header, channels);
    std::vector<Rgba> pixels = test_image(w, h);
    out.setFrameBuffer(pixels.data() - x0 - (size_t)y0 * w, 1, w);
    out.writePixels(h);
}

// A channel of an OutputFile: its name, type, sampling, and the values it holds.
struct Channel_ {
    std::string name;
    PixelType type;
    int xs, ys;
    std::vector<char> data;
};

// Writes a scanline file with OutputFile: channels named in list, of the given types and
// sampling, each sample a value that depends on the channel, x and y (R, G and B the test
// image's); the header's comments and chromaticities attributes when given.
static void write_channels(const std::string &name, std::vector<Channel_> list, int w, int h,
                           int x0, int y0, Compression compression, const std::string &comment = "",
                           const Chromaticities *chromaticities = nullptr)
{
    Box2i dw(V2i(x0, y0), V2i(x0 + w - 1, y0 + h - 1));
    Header header(dw, dw, 1, V2f(0, 0), 1, INCREASING_Y, compression);
    if (!comment.empty())
        addComments(header, comment);
    if (chromaticities != nullptr)
        addChromaticities(header, *chromaticities);
    FrameBuffer fb;
    for (size_t c = 0; c < list.size(); c++) {
        Channel_ &ch = list[c];
        header.channels().insert(ch.name, Channel(ch.type, ch.xs, ch.ys));
        int sw = w / ch.xs, sh = h / ch.ys;
        size_t size = ch.type == HALF ? 2 : 4;
        ch.data.resize((size_t)sw * sh * size);
        for (int sy = 0; sy < sh; sy++)
            for (int sx = 0; sx < sw; sx++) {
                int x = sx * ch.xs, y = sy * ch.ys;
                Rgba p = colour(x, y, w, h);
                float v = ch.name == "R"   ? float(p.r)
                          : ch.name == "G" ? float(p.g)
                          : ch.name == "B" ? float(p.b)
                          : ch.name == "A" ? float(p.a)
                                           : 0.125f * (float)(c + 1) + 0.01f * (float)(x + y);
                char *at = ch.data.data() + ((size_t)sy * sw + sx) * size;
                if (ch.type == HALF) {
                    half hv(v);
                    std::memcpy(at, &hv, 2);
                } else if (ch.type == FLOAT) {
                    std::memcpy(at, &v, 4);
                } else {
                    uint32_t u = (uint32_t)(1000 * v);
                    std::memcpy(at, &u, 4);
                }
            }
        char *base = ch.data.data() - (x0 / ch.xs + (size_t)(y0 / ch.ys) * sw) * size;
        fb.insert(ch.name, Slice(ch.type, base, size, size * sw, ch.xs, ch.ys));
    }
    OutputFile out(path(name).c_str(), header);
    out.setFrameBuffer(fb);
    out.writePixels(h);
}

// Writes a tiled RGBA file with mipmap levels (raytra reads level 0).
static void write_tiled(const std::string &name, int w, int h)
{
    TiledRgbaOutputFile out(path(name).c_str(), w, h, 16, 8, MIPMAP_LEVELS, ROUND_DOWN, WRITE_RGBA,
                            1, V2f(0, 0), 1, INCREASING_Y, ZIP_COMPRESSION);
    for (int level = 0; level < out.numLevels(); level++) {
        int lw = out.levelWidth(level), lh = out.levelHeight(level);
        std::vector<Rgba> pixels = test_image(lw, lh);
        out.setFrameBuffer(pixels.data(), 1, lw);
        out.writeTiles(0, out.numXTiles(level) - 1, 0, out.numYTiles(level) - 1, level);
    }
}

// Writes a file of two parts, each a small RGB image.
static void write_two_parts(const std::string &name)
{
    std::vector<Header> headers;
    for (int k = 0; k < 2; k++) {
        Header header(8, 4);
        header.setName(k == 0 ? "left" : "right");
        header.setType(SCANLINEIMAGE);
        header.channels().insert("R", Channel(HALF));
        header.channels().insert("G", Channel(HALF));
        header.channels().insert("B", Channel(HALF));
        headers.push_back(header);
    }
    MultiPartOutputFile out(path(name).c_str(), headers.data(), 2);
    std::vector<half> plane(8 * 4, half(0.5f));
    for (int k = 0; k < 2; k++) {
        OutputPart part(out, k);
        FrameBuffer fb;
        for (const char *c : {"R", "G", "B"})
            fb.insert(c, Slice(HALF, (char *)plane.data(), 2, 2 * 8));
        part.setFrameBuffer(fb);
        part.writePixels(4);
    }
}

// Writes a deep scanline file: one Z sample a pixel.
static void write_deep(const std::string &name)
{
    const int w = 4, h = 3;
    Header header(w, h);
    header.channels().insert("Z", Channel(FLOAT));
    header.setType(DEEPSCANLINE);
    header.compression() = ZIPS_COMPRESSION;
    DeepScanLineOutputFile out(path(name).c_str(), header);
    std::vector<unsigned int> counts(w * h, 1);
    std::vector<float> depth(w * h, 2.0f);
    std::vector<float *> pointers(w * h);
    for (int k = 0; k < w * h; k++)
        pointers[k] = &depth[k];
    DeepFrameBuffer fb;
    fb.insertSampleCountSlice(
        Slice(UINT, (char *)counts.data(), sizeof(unsigned), sizeof(unsigned) * w));
    fb.insert("Z", DeepSlice(FLOAT, (char *)pointers.data(), sizeof(float *), sizeof(float *) * w,
                             sizeof(float)));
    out.setFrameBuffer(fb);
    out.writePixels(h);
}

// The value of channel c at pixel (x, y) of the data window in write_plain's files.
static float value(char c, int x, int y)
{
    switch (c) {
    case 'R': return x * 0.25f;
    case 'G': return y * 0.5f;
    case 'B': return 0.1f;
    case 'Y': return 0.75f + x;
    default: return 0.5f; // A, and any other
    }
}

// Writes a w x h file of the channels named by the letters of names, of the given type and
// compression, its data window starting at (x0, y0), in scanlines or, when tile > 0, in
// tiles of tile x tile pixels; the samples are value()'s, converted by the library.
static void write_plain(const std::string &name, const std::string &names, PixelType type,
                        Compression compression, int w, int h, int x0, int y0, int tile = 0)
{
    Box2i dw(V2i(x0, y0), V2i(x0 + w - 1, y0 + h - 1));
    Header header(dw, dw, 1, V2f(0, 0), 1, INCREASING_Y, compression);
    if (tile > 0)
        header.setTileDescription(TileDescription(tile, tile, ONE_LEVEL));
    // The samples in the channel's own type: the library converts when it reads, not
    // when it writes.
    size_t size = type == HALF ? 2 : 4;
    std::vector<char> planes(names.size() * w * h * size);
    FrameBuffer fb;
    for (size_t k = 0; k < names.size(); k++) {
        char *plane = planes.data() + k * w * h * size;
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                float v = value(names[k], x, y);
                half hv(v);
                std::memcpy(plane + ((size_t)y * w + x) * size, type == HALF ? (void *)&hv : &v,
                            size);
            }
        std::string channel(1, names[k]);
        header.channels().insert(channel, Channel(type));
        fb.insert(channel, Slice(type, plane - (x0 + (long)y0 * w) * (long)size, size, size * w));
    }
    if (tile > 0) {
        TiledOutputFile out(path(name).c_str(), header);
        out.setFrameBuffer(fb);
        out.writeTiles(0, out.numXTiles() - 1, 0, out.numYTiles() - 1);
    } else {
        OutputFile out(path(name).c_str(), header);
        out.setFrameBuffer(fb);
        out.writePixels(h);
    }
}

// Writes every test file.
int main(int argc, char **argv)
{
    if (argc == 3 && std::strcmp(argv[1], "--floats") == 0) {
        folder = ".";
        try {
            expect_channels(argv[2]);
        } catch (const std::exception &e) {
            std::fprintf(stderr, "exr_writer: %s\n", e.what());
            return 1;
        }
        return 0;
    }
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s FOLDER | --floats FILE.exr\n", argv[0]);
        return 2;
    }
    folder = argv[1];
    try {
        // Plain layouts, scanline and tiled, half and float (value()'s samples): 40 rows in
        // chunks of 16, the last one short; partial tiles at the right and the bottom.
        write_plain("half.exr", "RGBA", HALF, ZIP_COMPRESSION, 9, 40, 0, 0);
        write_plain("piz.exr", "BGR", HALF, PIZ_COMPRESSION, 33, 70, 0, 0);
        write_plain("float.exr", "RGB", FLOAT, NO_COMPRESSION, 5, 3, -2, 10);
        write_plain("rle.exr", "RGB", FLOAT, RLE_COMPRESSION, 7, 70, 3, 1);
        write_plain("zips.exr", "RGB", HALF, ZIPS_COMPRESSION, 6, 5, 0, 0);
        write_plain("tiled.exr", "RGB", HALF, ZIP_COMPRESSION, 37, 21, 0, 0, 16);
        write_plain("tiled-offset.exr", "BGRA", FLOAT, PIZ_COMPRESSION, 37, 21, 5, -3, 16);
        write_plain("grey.exr", "Y", HALF, ZIP_COMPRESSION, 4, 2, 0, 0);
        write_plain("alpha.exr", "A", HALF, ZIP_COMPRESSION, 2, 2, 0, 0);
        write_plain("escape.exr", "\033", HALF, ZIP_COMPRESSION, 2, 2, 0, 0);
        write_plain("none.exr", "RGB", FLOAT, NO_COMPRESSION, 5, 3, 0, 0);
        write_plain("zip.exr", "RGB", HALF, ZIP_COMPRESSION, 8, 20, 0, 0);
        // RgbaOutputFile's layouts, as RgbaInputFile reads them.
        write_rgba("rgba.exr", WRITE_RGBA, 37, 23, 0, 0, ZIP_COMPRESSION);
        write_rgba("rgba-decreasing.exr", WRITE_RGBA, 37, 40, 3, -7, ZIP_COMPRESSION, DECREASING_Y);
        write_rgba("yc.exr", WRITE_YC, 64, 48, 0, 0, ZIP_COMPRESSION);
        write_rgba("yca.exr", WRITE_YCA, 50, 34, -6, 4, PIZ_COMPRESSION, DECREASING_Y);
        Chromaticities rec2020(V2f(0.708f, 0.292f), V2f(0.170f, 0.797f), V2f(0.131f, 0.046f),
                               V2f(0.3127f, 0.3290f));
        write_rgba("yc-rec2020.exr", WRITE_YC, 30, 20, 0, 0, NO_COMPRESSION, INCREASING_Y,
                   &rec2020);
        write_rgba("yc-tiny.exr", WRITE_YC, 2, 2, 0, 0, RLE_COMPRESSION);
        write_rgba("y.exr", WRITE_Y, 21, 13, 0, 0, ZIP_COMPRESSION);
        write_rgba("ya.exr", WRITE_YA, 21, 13, 3, -5, NO_COMPRESSION);
        // The other compressions, lossy ones included: raytra decodes through the C
        // library, OpenEXR's reader through the C++ one.
        write_rgba("rgba-pxr24.exr", WRITE_RGBA, 37, 23, 0, 0, PXR24_COMPRESSION);
        write_rgba("rgba-b44.exr", WRITE_RGBA, 37, 23, 0, 0, B44_COMPRESSION);
        write_rgba("yca-b44a.exr", WRITE_YCA, 36, 22, 0, 0, B44A_COMPRESSION);
        write_rgba("rgba-dwaa.exr", WRITE_RGBA, 37, 23, 0, 0, DWAA_COMPRESSION);
        write_rgba("yc-dwab.exr", WRITE_YC, 40, 30, 0, 0, DWAB_COMPRESSION);
        write_rgba("y-zips.exr", WRITE_Y, 21, 13, 0, 0, ZIPS_COMPRESSION);
        for (const char *name : {"rgba.exr", "rgba-decreasing.exr", "yc.exr", "yca.exr", "yc-rec2020.exr", "yc-tiny.exr",
                                 "y.exr", "ya.exr", "rgba-pxr24.exr", "rgba-b44.exr",
                                 "yca-b44a.exr", "rgba-dwaa.exr", "yc-dwab.exr", "y-zips.exr"})
            expect_rgba_input(name);
        // Grey, alpha and depth: three channels of which raytra reads one.
        write_channels("yaz.exr",
                       {{"Y", HALF, 1, 1, {}}, {"A", HALF, 1, 1, {}}, {"Z", FLOAT, 1, 1, {}}}, 17,
                       9, 0, 0, ZIP_COMPRESSION);
        expect_rgba_input("yaz.exr");
        // Many channels of all types and samplings, and a long comment: the header holds
        // more than 4 KiB before the data window.
        std::vector<Channel_> many = {{"R", HALF, 1, 1, {}},
                                      {"G", HALF, 1, 1, {}},
                                      {"B", HALF, 1, 1, {}},
                                      {"A", HALF, 1, 1, {}}};
        for (int k = 0; k < 60; k++) {
            static const PixelType types[3] = {HALF, FLOAT, UINT};
            static const int samplings[4] = {1, 2, 4, 1};
            many.push_back({"aov" + std::to_string(k) + ".value",
                            types[k % 3],
                            samplings[k % 4],
                            samplings[(k / 4) % 4],
                            {}});
        }
        std::string comment;
        while (comment.size() < 6000)
            comment += "A comment that makes the header long, as some tools write one. ";
        write_channels("many.exr", many, 40, 24, 0, 0, ZIP_COMPRESSION, comment);
        expect_rgba_input("many.exr");
        // R, G and B with a Y: raytra reads R, G and B; compressed with PIZ it is refused
        // (OpenEXR's RGBA interface, which decodes PIZ for raytra, would read Y as grey).
        std::vector<Channel_> rgby = {{"R", FLOAT, 1, 1, {}},
                                      {"G", FLOAT, 1, 1, {}},
                                      {"B", FLOAT, 1, 1, {}},
                                      {"Y", FLOAT, 1, 1, {}}};
        write_channels("rgby.exr", rgby, 13, 11, 0, 0, ZIP_COMPRESSION);
        expect_channels("rgby.exr");
        write_channels("rgby-piz.exr", rgby, 13, 11, 0, 0, PIZ_COMPRESSION);
        // R, G and B with subsampled channels raytra does not read, uncompressed (chunks of
        // one line, some without the subsampled ones) and compressed.
        std::vector<Channel_> sub = {{"B", HALF, 1, 1, {}},  {"BY", HALF, 2, 2, {}},
                                     {"G", HALF, 1, 1, {}},  {"R", HALF, 1, 1, {}},
                                     {"RY", HALF, 2, 2, {}}, {"Z", FLOAT, 4, 2, {}}};
        write_channels("rgb-sub.exr", sub, 24, 10, 0, 0, ZIP_COMPRESSION);
        write_channels("rgb-sub-none.exr", sub, 24, 10, -4, 2, NO_COMPRESSION);
        expect_channels("rgb-sub.exr");
        expect_channels("rgb-sub-none.exr");
        write_tiled("tiled-mipmap.exr", 45, 30);
        expect_rgba_input("tiled-mipmap.exr");
        // Files raytra refuses.
        write_two_parts("two-parts.exr");
        write_deep("deep.exr");
        write_channels("uint-y.exr", {{"Y", UINT, 1, 1, {}}}, 4, 4, 0, 0, ZIP_COMPRESSION);
        write_channels("chroma-only.exr", {{"BY", HALF, 2, 2, {}}, {"RY", HALF, 2, 2, {}}}, 4, 4, 0,
                       0, ZIP_COMPRESSION);
        write_channels("rg.exr", {{"G", HALF, 1, 1, {}}, {"R", HALF, 1, 1, {}}}, 4, 4, 0, 0,
                       ZIP_COMPRESSION);
        write_channels("y-sub.exr", {{"Y", HALF, 2, 2, {}}}, 4, 4, 0, 0, ZIP_COMPRESSION);
        Chromaticities collinear(V2f(0.1f, 0.3f), V2f(0.2f, 0.3f), V2f(0.3f, 0.3f),
                                 V2f(0.3127f, 0.3290f));
        write_channels("yc-collinear.exr",
                       {{"BY", HALF, 2, 2, {}}, {"RY", HALF, 2, 2, {}}, {"Y", HALF, 1, 1, {}}}, 4,
                       4, 0, 0, ZIP_COMPRESSION, "", &collinear);
    } catch (const std::exception &e) {
        std::fprintf(stderr, "exr_writer: %s\n", e.what());
        return 1;
    }
    return 0;
}
