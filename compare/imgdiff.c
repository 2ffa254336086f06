/* imgdiff.c: compares two images, PNG, PFM or EXR, and tells whether they match. */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

#include "diffopt.h"
#include "image.h"
#include "image_read.h"
#include "imgdiff.h"
#include "imgfile.h"
#include "imgmap.h"
#include "mcref.h"
#include "outfile.h"
#include "pixdiff.h"
#include "statdiff.h"
#include "statstandard.h"
#include "toolopt.h"

/* The largest image of another size shrunk for --thumb: a larger one is surely a mistake,
 * or a decompression bomb. */
#define THUMB_MAX_PIXELS (4096L * 4096)

/* imgdiff's options, from which the parsing and --help are made; the enum names each
 * one's place in the table. */
enum {
    OPT_THRESHOLD,
    OPT_ALLOW,
    OPT_DIFF,
    OPT_THUMB,
    OPT_DIFF_THUMB,
    OPT_SCALE,
    OPT_COVER,
    OPT_STANDARD,
    OPT_QUIET,
    OPT_MACHINE,
    OPT_HELP
};
static const ToolOption options[] = {
    {"threshold", 0, "T",
     "a pixel differs when one of its channels differs by more\n"
     "than T, a number or a fraction such as 8/255; 2/255\nis more than 2 steps of 8 bits",
     IMGDIFF_THRESHOLD_TEXT},
    {"allow", 0, "F", "the images match when at most the fraction F of the\npixels differ",
     IMGDIFF_ALLOW_TEXT},
    {"diff", 0, "FILE",
     "write a heat map of the differences to FILE (.png or\n.pfm): black "
     "where a pixel is exactly equal; any\ndifference, even one within the threshold, is at "
     "least\ndark blue, then the colours run through purple, red\nand yellow to white",
     NULL},
    {"thumb", 0, "FILE",
     "write B shrunk by a whole factor to at most 320\npixels a side to "
     "FILE, each pixel a block's mean;\nalso when the sizes differ, up to 4096 x 4096 pixels",
     NULL},
    {"diff-thumb", 0, "FILE",
     "write the heat map so shrunk to FILE, each pixel\nits block's "
     "brightest, so that one differing pixel\nstill shows",
     NULL},
    {"scale", 0, "S",
     "the difference that is white in the heat map, larger\nones too "
     "(default: the largest difference found)",
     NULL},
    {"cover", 0, NULL,
     "judge coverage, not values: a pixel differs when A\nis drawn there and B is not (a pixel is "
     "drawn when\na channel is above T; the background is black)",
     NULL},
    {"standard", 0, "NAME",
     "against a statistical reference (a Monte Carlo render):\nthe course's soft shadow that "
     "passes, good (stratified\nor correlated light samples) or ok (random points on\nthe "
     "light)",
     "good"},
    {"quiet", 'q', NULL, "print only the verdict", NULL},
    {"machine", 0, NULL,
     "print the figures as NAME VALUE lines instead, for\nprograms "
     "(grader/grade reads them; docs/grading.md lists\nthem)",
     NULL},
    {"help", 'h', NULL, "show this help and exit", NULL},
};
enum { OPTION_COUNT = sizeof options / sizeof options[0] };

/* Prints the usage, the options and their defaults. */
static void print_help(void)
{
    printf("Usage: imgdiff [options] A B\n"
           "Compares two images of the same size, each a PNG (8 or 16 bits, any colour\n"
           "type), a PFM or an EXR, and tells whether they match.\n"
           "\n"
           "Values are compared on a scale of 0 to 1 as the files hold them: a PNG's\n"
           "as stored (raytra writes them sRGB-encoded unless given --linear), a PFM's\n"
           "or an EXR's linear. A PNG compared with a linear image meets it as raytra\n"
           "would write it to a PNG: clamped to [0, 1], sRGB-encoded, rounded to 8 bits.\n"
           "Transparent PNG pixels are taken as drawn over black.\n"
           "\n"
           "Options:\n");
    toolopt_print(stdout, options, sizeof options[0], OPTION_COUNT);
    printf("\n"
           "The report gives the largest difference in each channel (also in steps of\n"
           "8 bits, x/255), the mean absolute difference, the RMSE, the PSNR (peak 1),\n"
           "the pixels that differ and the box around them (x0,y0)-(x1,y1), y from\n"
           "the top, and the verdict, PASS or FAIL.\n"
           "\n"
           "Exit status: 0 when the images match, 1 when they do not, 2 on trouble (a\n"
           "missing or unreadable file, different sizes, a bad option). The defaults\n"
           "are those of raytra's image-regression tests (compare/imgdiff.h).\n");
}

/* Stores the value of option k in the DiffOptions `state`: for --threshold, --allow and
 * --scale a number, a decimal or a fraction N/D (2/255); false (reported) when it is not
 * a valid one. */
static bool set_option(void *state, int k, const char *value)
{
    DiffOptions *o = state;
    if (k == OPT_QUIET || k == OPT_MACHINE || k == OPT_HELP || k == OPT_COVER) {
        *(k == OPT_QUIET  ? &o->quiet
          : k == OPT_HELP ? &o->help
          : k == OPT_COVER ? &o->cover
                           : &o->machine) = true;
        return true;
    }
    if (k == OPT_STANDARD) {
        if (statstandard_from_name(value, &o->standard))
            return true;
        fprintf(stderr, "imgdiff: --standard takes good or ok, got '%s'\n", value);
        return false;
    }
    if (k == OPT_DIFF || k == OPT_THUMB || k == OPT_DIFF_THUMB) {
        *(k == OPT_DIFF ? &o->diff_path : k == OPT_THUMB ? &o->thumb_path : &o->diff_thumb) = value;
        return true;
    }
    char *end;
    double v = strtod(value, &end);
    if (end != value && *end == '/') {
        const char *denominator = end + 1;
        double d = strtod(denominator, &end);
        v = end != denominator ? v / d : NAN; /* N/0 is not finite either */
    }
    bool number = end != value && *end == '\0' && isfinite(v);
    if (k == OPT_THRESHOLD && number && v >= 0)
        o->threshold = v;
    else if (k == OPT_ALLOW && number && v >= 0 && v <= 1)
        o->allow = v;
    else if (k == OPT_SCALE && number && v > 0)
        o->scale = v;
    else {
        const char *wanted = k == OPT_ALLOW   ? "a fraction from 0 to 1"
                             : k == OPT_SCALE ? "a number above 0, or a fraction such as 8/255"
                                              : "a number from 0 up, or a fraction such as 2/255";
        fprintf(stderr, "imgdiff: --%s takes %s, got '%s'\n", options[k].name, wanted, value);
        return false;
    }
    return true;
}

/* Reads the command line into o (options may follow the images); false (reported) when it
 * is not a valid one. */
static bool parse_args(int argc, char **argv, DiffOptions *o)
{
    *o = (DiffOptions){.threshold = IMGDIFF_THRESHOLD, .allow = IMGDIFF_ALLOW};
    if (!toolopt_parse("imgdiff", options, sizeof options[0], OPTION_COUNT, argc, argv, set_option,
                       o))
        return false;
    if (argc - optind > 2) {
        fprintf(stderr, "imgdiff: unexpected argument '%s': give two images\n", argv[optind + 2]);
        return false;
    }
    for (int k = 0; optind + k < argc; k++)
        o->paths[k] = argv[optind + k];
    if (!o->help && argc - optind < 2) {
        fprintf(stderr, "imgdiff: give two images to compare (imgdiff --help shows how)\n");
        return false;
    }
    return true;
}

/* Tells, before any work, whether an image asked for (the heat map, a thumbnail) can be
 * written to path; reports why not. */
static bool check_output(const DiffOptions *o, const char *path)
{
    Error err;
    /* The same file, however it is spelt (./a.png, d/../a.png, a link, a hard link). */
    struct stat map, input;
    for (int k = 0; k < 2 && stat(path, &map) == 0; k++)
        if (stat(o->paths[k], &input) == 0 && input.st_dev == map.st_dev &&
            input.st_ino == map.st_ino) {
            fprintf(stderr, "imgdiff: %s would overwrite %s, an image being compared\n", path,
                    o->paths[k]);
            return false;
        }
    if (image_format_for_path(path) == IMAGE_FORMAT_UNKNOWN)
        error_set(&err, "unknown image format (use .png or .pfm)");
    else if (outfile_check(path, &err))
        return true;
    fprintf(stderr, "imgdiff: cannot write '%s': %s\n", path, err.text);
    return false;
}

/* Tells, from the headers alone, whether both images can be read and have the same size;
 * reports why not. Nothing is decoded before: an image's pixels may be a bomb. */
static bool check_headers(const DiffOptions *o, ImgFileKind kind[2])
{
    int w[2], h[2];
    Error err;
    for (int k = 0; k < 2; k++)
        if (!imgfile_header(o->paths[k], &kind[k], &w[k], &h[k], &err)) {
            fprintf(stderr, "imgdiff: cannot read '%s': %s\n", o->paths[k], err.text);
            return false;
        }
    if (w[0] == w[1] && h[0] == h[1])
        return true;
    if (o->machine)
        printf("sizes %d %d %d %d\n", w[0], h[0], w[1], h[1]);
    fprintf(stderr, "imgdiff: sizes differ: %s is %d x %d, %s is %d x %d\n", o->paths[0], w[0],
            h[0], o->paths[1], w[1], h[1]);
    /* B is still shown, unless its size makes it a likely bomb. */
    Image b;
    if (o->thumb_path != NULL && (long)w[1] * h[1] <= THUMB_MAX_PIXELS &&
        image_read(&b, o->paths[1], &err)) {
        imgmap_write_thumb(&b, false, imgfile_encoding(kind[1]), o->thumb_path);
        image_free(&b);
    }
    return false;
}

/* Runs imgdiff: exit status 0 when the images match, 1 when not, 2 on trouble. */
int main(int argc, char **argv)
{
    DiffOptions o;
    if (!parse_args(argc, argv, &o))
        return EXIT_TROUBLE;
    if (o.help) {
        print_help();
        return EXIT_MATCH;
    }
    ImgFileKind kind[2];
    const char *outputs[] = {o.diff_path, o.thumb_path, o.diff_thumb};
    for (int k = 0; k < 3; k++)
        if (outputs[k] != NULL && !check_output(&o, outputs[k]))
            return EXIT_TROUBLE;
    if (!check_headers(&o, kind))
        return EXIT_TROUBLE;
    /* A statistical reference of Monte Carlo renders: judged by statistics (statdiff.c). */
    if (kind[0] == IMGFILE_EXR && mcref_is(o.paths[0]))
        return statdiff_run(&(StatDiffRequest){o.paths[0], o.paths[1], kind[1], o.diff_path,
                                               o.diff_thumb, o.thumb_path, o.quiet, o.machine,
                                               o.standard});
    Image img[2] = {{0}};
    Error err;
    int read = 0;
    while (read < 2 && image_read(&img[read], o.paths[read], &err))
        read++;
    if (read < 2)
        fprintf(stderr, "imgdiff: cannot read '%s': %s\n", o.paths[read], err.text);
    int status = read == 2 ? pixdiff_run(img, kind, &o) : EXIT_TROUBLE;
    for (int k = 0; k < read; k++)
        image_free(&img[k]);
    return status;
}
