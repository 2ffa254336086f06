/* pixdiff.c: two images of one size compared pixel by pixel: how they differ, and the verdict. */
#include "pixdiff.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "imgmap.h"

/* How two images of the same size differ. */
typedef struct {
    double max[3];           /* the largest difference in R, G and B */
    double largest_finite;   /* the largest finite difference in any channel */
    long nonfinite;          /* pixels with a NaN or infinite channel in either image */
    double sum, sum_squares; /* of the differences of every channel of every pixel */
    long differing;          /* pixels with a channel difference above the threshold */
    int x0, y0, x1, y1;      /* the box around those pixels, y from the top */
} Diff;

/* Tells whether pixel k of img is drawn: a channel above threshold, not the black background. */
static bool drawn(const Image *img, long k, double threshold)
{
    const float *p = &img->pixels[3 * k];
    return p[0] > threshold || p[1] > threshold || p[2] > threshold;
}

/* Measures how a and b, of the same size, differ, counting the pixels beyond threshold; with
 * cover, counting instead the pixels drawn in a and not in b. */
static Diff diff_images(const Image *a, const Image *b, double threshold, bool cover)
{
    Diff d = {.x0 = a->width, .y0 = a->height, .x1 = -1, .y1 = -1};
    for (int y = 0; y < a->height; y++)
        for (int x = 0; x < a->width; x++) {
            double e[3], largest = imgmap_pixel_diff(a, b, (long)y * a->width + x, e);
            for (int c = 0; c < 3; c++) {
                d.max[c] = fmax(d.max[c], e[c]);
                d.sum += e[c];
                d.sum_squares += e[c] * e[c];
                if (isfinite(e[c]))
                    d.largest_finite = fmax(d.largest_finite, e[c]);
            }
            d.nonfinite += isinf(largest);
            long k = (long)y * a->width + x;
            if (cover ? drawn(a, k, threshold) && !drawn(b, k, threshold) : largest > threshold) {
                d.differing++;
                d.x0 = x < d.x0 ? x : d.x0;
                d.y0 = y < d.y0 ? y : d.y0;
                d.x1 = x > d.x1 ? x : d.x1;
                d.y1 = y > d.y1 ? y : d.y1;
            }
        }
    return d;
}

/* Prints the measures of d for images of width x height pixels: in words, or with
 * --machine with the tolerances as NAME VALUE lines with enough digits to be read back
 * exactly; top is the heat map's scale, 0 when none was written. */
static void print_figures(const Diff *d, int width, int height, double top, const DiffOptions *o)
{
    long pixels = (long)width * height;
    double mean = d->sum / (3.0 * pixels), rmse = sqrt(d->sum_squares / (3.0 * pixels));
    /* PSNR = 10 log10(peak^2 / MSE) with peak 1: equal images, no noise, give inf. */
    double psnr = -20 * log10(rmse), t = o->threshold;
    if (o->machine) {
        printf("threshold %.9g\nallow %.9g\nsize %d %d\nmax %.9g %.9g %.9g\nmean %.9g\n"
               "rmse %.9g\npsnr %.9g\ndiffering %ld %ld\n",
               t, o->allow, width, height, d->max[0], d->max[1], d->max[2], mean, rmse, psnr,
               d->differing, pixels);
        if (d->differing > 0)
            printf("box %d %d %d %d\n", d->x0, d->y0, d->x1, d->y1);
        if (top > 0)
            printf("heat_scale %.9g\n", top);
        if (d->nonfinite > 0)
            printf("nonfinite %ld\n", d->nonfinite);
        return;
    }
    /* Values in 255ths and percentages to 3 digits, RMSE to 4, PSNR to 0.01 dB: as grader/grade
     * writes them in its report and messages, so that both give the same figures. */
    printf("size: %d x %d pixels\n", width, height);
    printf("largest difference (R, G, B): %.3g, %.3g, %.3g /255\n", d->max[0] * 255,
           d->max[1] * 255, d->max[2] * 255);
    printf("mean absolute difference: %.3g /255\n", mean * 255);
    if (isinf(psnr))
        printf("RMSE: %.4g\nPSNR: inf (equal)\n", rmse);
    else
        printf("RMSE: %.4g\nPSNR: %.2f dB\n", rmse, psnr);
    printf("differing pixels: %ld (%.3g%%) of %ld differ by more than %.3g/255\n", d->differing,
           100.0 * d->differing / pixels, pixels, t * 255);
    if (d->differing > 0)
        printf("differing region: (%d,%d)-(%d,%d), y from the top\n", d->x0, d->y0, d->x1, d->y1);
    if (d->nonfinite > 0)
        printf("non-finite pixels: %ld (NaN or infinite in either image)\n", d->nonfinite);
}

/* Returns the name of the file at path, without its folders. */
static const char *file_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash != NULL ? slash + 1 : path;
}

/* Prints the verdict line; returns the exit status it means. */
static int print_verdict(const Diff *d, long pixels, const DiffOptions *o)
{
    /* A NaN or infinite pixel is a bug in the renderer, whatever the tolerances. */
    bool pass = (double)d->differing <= o->allow * pixels && d->nonfinite == 0;
    if (o->machine)
        printf("verdict %s\n", pass ? "PASS" : "FAIL");
    else if (d->nonfinite > 0)
        printf("FAIL: %ld pixel%s not finite (NaN or infinite)\n", d->nonfinite,
               d->nonfinite == 1 ? " is" : "s are");
    else if (o->cover)
        printf("%s: %.3g%% of the pixels are drawn in %s (A) and not in %s (B: black, at most "
               "%.3g/255), %s the %.3g%% allowed\n",
               pass ? "PASS" : "FAIL", 100.0 * d->differing / pixels, file_name(o->paths[0]),
               file_name(o->paths[1]), o->threshold * 255, pass ? "within" : "more than",
               o->allow * 100);
    else if (d->max[0] == 0 && d->max[1] == 0 && d->max[2] == 0)
        printf("PASS: the images are identical\n");
    else if (d->differing == 0)
        printf("PASS: no pixel differs by more than %.3g/255\n", o->threshold * 255);
    else
        printf("%s: %.3g%% of the pixels differ by more than %.3g/255, %s the %.3g%% allowed\n",
               pass ? "PASS" : "FAIL", 100.0 * d->differing / pixels, o->threshold * 255,
               pass ? "within" : "more than", o->allow * 100);
    return pass ? EXIT_MATCH : EXIT_DIFFER;
}

/* Compares the images img, of kinds kind, reports, writes the heat map if asked; returns
 * the exit status. */
int pixdiff_run(Image img[2], const ImgFileKind kind[2], const DiffOptions *o)
{
    const Image *a = &img[0], *b = &img[1];
    if (a->width != b->width || a->height != b->height) {
        fprintf(stderr, "imgdiff: '%s' changed while it was read\n", o->paths[1]);
        return EXIT_TROUBLE;
    }
    if (o->thumb_path != NULL &&
        !imgmap_write_thumb(b, false, imgfile_encoding(kind[1]), o->thumb_path))
        return EXIT_TROUBLE;
    /* A PNG against linear values (a PFM's, an EXR's): each linear value is encoded as
     * raytra encodes its PNGs, clamped to [0, 1], given the sRGB curve and rounded to 8
     * bits. A non-finite value stays as it is, to be reported. */
    Image *linear = &img[kind[0] == IMGFILE_PNG]; /* the linear one, if one is */
    if ((kind[0] == IMGFILE_PNG) != (kind[1] == IMGFILE_PNG)) {
        for (long k = 0; k < 3L * linear->width * linear->height; k++)
            if (isfinite(linear->pixels[k]))
                linear->pixels[k] =
                    (float)(image_encode_8bit(linear->pixels[k], PNG_ENCODING_SRGB) / 255.0);
        if (!o->quiet && !o->machine)
            printf("note: %s holds linear values: compared as raytra would write them to "
                   "a PNG (clamped to [0, 1], sRGB, 8 bits)\n",
                   o->paths[linear - img]);
    }
    Diff d = diff_images(a, b, o->threshold, o->cover);
    if (!o->quiet && !o->machine)
        print_figures(&d, a->width, a->height, 0, o);
    /* Equal images get an all-black map; the scale then only needs to be positive. */
    double top = o->scale > 0 ? o->scale : d.largest_finite > 0 ? d.largest_finite : 1.0 / 255;
    bool heat = o->diff_path != NULL || o->diff_thumb != NULL;
    if (heat && !imgmap_write_heat(a, b, top, o->diff_path, o->diff_thumb))
        return EXIT_TROUBLE;
    if (o->diff_path != NULL && !o->quiet && !o->machine)
        printf("heat map: black where equal, white at %.3g/255, written to %s\n", top * 255,
               o->diff_path);
    if (o->machine)
        print_figures(&d, a->width, a->height, heat ? top : 0, o);
    return print_verdict(&d, (long)a->width * a->height, o);
}
