/* imgmap.c: the pictures imgdiff draws: heat maps of two images' differences, and thumbnails. */
#include "imgmap.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* The heat map's colours, evenly spread from the smallest difference to the scale's top. */
static const Color ramp[] = {
    {0.0, 0.0, 0.35}, /* dark blue: the smallest difference, still unlike black */
    {0.5, 0.0, 0.75}, /* purple */
    {1.0, 0.0, 0.0},  /* red */
    {1.0, 1.0, 0.0},  /* yellow */
    {1.0, 1.0, 1.0},  /* white: the top of the scale, and above */
};
#define RAMP_STOPS ((int)(sizeof ramp / sizeof ramp[0]))

/* The longest side of a thumbnail: three fit side by side on a laptop's screen. */
#define THUMB_SIDE 320

/* Writes the differences of the channels of pixel k of a and b into e; returns the
 * largest. A NaN or an infinity in either is an infinite difference, even against
 * another: such a pixel is broken, never equal. */
double imgmap_pixel_diff(const Image *a, const Image *b, long k, double e[3])
{
    double largest = 0;
    for (int c = 0; c < 3; c++) {
        float p = a->pixels[3 * k + c], q = b->pixels[3 * k + c];
        e[c] = isfinite(p) && isfinite(q) ? fabs((double)p - (double)q) : INFINITY;
        largest = fmax(largest, e[c]);
    }
    return largest;
}

/* Returns the heat map's colour for difference e on a scale whose top is top: black
 * for an exactly equal pixel, at least dark blue for any difference at all. */
static Color heat_color(double e, double top)
{
    if (e == 0)
        return color(0, 0, 0);
    double t = fmin(e / top, 1.0) * (RAMP_STOPS - 1);
    int k = t < RAMP_STOPS - 2 ? (int)t : RAMP_STOPS - 2; /* the stops t lies between */
    double f = t - k;
    return color_add(color_scale(ramp[k], 1 - f), color_scale(ramp[k + 1], f));
}

/* Writes img to path shrunk by a whole factor to at most THUMB_SIDE pixels a side, each
 * pixel the mean of its block, or with peaks its brightest pixel, so that a heat map's
 * single differing pixel stays; false (reported) when it cannot. */
bool imgmap_write_thumb(const Image *img, bool peaks, PngEncoding encoding, const char *path)
{
    int side = img->width > img->height ? img->width : img->height;
    int f = (side + THUMB_SIDE - 1) / THUMB_SIDE;
    Image thumb;
    Error err;
    error_set(&err, "not enough memory");
    bool ok = image_init(&thumb, (img->width + f - 1) / f, (img->height + f - 1) / f);
    for (int y = 0; ok && y < thumb.height; y++)
        for (int x = 0; x < thumb.width; x++) {
            Color sum = color(0, 0, 0), peak = image_get(img, x * f, y * f);
            int n = 0;
            for (int v = y * f; v < (y + 1) * f && v < img->height; v++)
                for (int u = x * f; u < (x + 1) * f && u < img->width; u++, n++) {
                    Color c = image_get(img, u, v);
                    sum = color_add(sum, c);
                    peak = c.r + c.g + c.b > peak.r + peak.g + peak.b ? c : peak;
                }
            image_set(&thumb, x, y, peaks ? peak : color_scale(sum, 1.0 / n));
        }
    ok = ok && image_write(&thumb, path, encoding, &err);
    if (!ok)
        fprintf(stderr, "imgdiff: cannot write '%s': %s\n", path, err.text);
    image_free(&thumb);
    return ok;
}

/* Writes the heat map of a against b, scaled so that top is white, to path and shrunk to
 * thumb_path (either may be NULL), linear so that the ramp's colours are stored as
 * chosen; false (reported) when it cannot. */
bool imgmap_write_heat(const Image *a, const Image *b, double top, const char *path,
                       const char *thumb_path)
{
    long pixels = (long)a->width * a->height;
    float *level = malloc((size_t)pixels * sizeof *level);
    double e[3];
    if (level == NULL) {
        fprintf(stderr, "imgdiff: not enough memory for the heat map\n");
        return false;
    }
    for (long k = 0; k < pixels; k++)
        level[k] = (float)imgmap_pixel_diff(a, b, k, e);
    bool ok = imgmap_write_levels(level, a->width, a->height, top, path, thumb_path);
    free(level);
    return ok;
}

/* Writes the map of level, a value a pixel (width x height, rows from the top), on the heat
 * map's colours with top white, to path and shrunk to thumb_path (either may be NULL);
 * false (reported) when it cannot. Statistical comparisons draw their z-scores so. */
bool imgmap_write_levels(const float *level, int width, int height, double top, const char *path,
                         const char *thumb_path)
{
    Image map;
    if (!image_init(&map, width, height)) {
        fprintf(stderr, "imgdiff: not enough memory for the heat map\n");
        return false;
    }
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++)
            image_set(&map, x, y, heat_color(level[(long)y * width + x], top));
    Error err;
    bool ok = path == NULL || image_write(&map, path, PNG_ENCODING_LINEAR, &err);
    if (!ok)
        fprintf(stderr, "imgdiff: cannot write '%s': %s\n", path, err.text);
    ok = ok &&
         (thumb_path == NULL || imgmap_write_thumb(&map, true, PNG_ENCODING_LINEAR, thumb_path));
    image_free(&map);
    return ok;
}
