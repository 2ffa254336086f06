/* mcstats.c: makes a statistical reference (mcref.h) from renders of one scene with independent
 * seeds. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "image.h"
#include "image_read.h"
#include "mcref.h"
#include "toolopt.h"

/* What the command line asks for. */
typedef struct {
    int p, s;
    const char *seeds;
    bool help;
} StatsOptions;

enum { OPT_P, OPT_S, OPT_SEEDS, OPT_HELP };
static const ToolOption options[] = {
    {"p", 0, "P", "the P the renders were made with (recorded in the header)", NULL},
    {"s", 0, "S", "the S the renders were made with (recorded in the header)", NULL},
    {"seeds", 0, "TEXT", "their seeds, as words (recorded in the header)", NULL},
    {"help", 'h', NULL, "show this help and exit", NULL},
};
enum { OPTION_COUNT = sizeof options / sizeof options[0] };

/* Stores the value of option k in the StatsOptions `state`; false (reported) when bad. */
static bool set_option(void *state, int k, const char *value)
{
    StatsOptions *o = state;
    if (k == OPT_HELP) {
        o->help = true;
        return true;
    }
    if (k == OPT_SEEDS) {
        o->seeds = value;
        return true;
    }
    char *end;
    long v = strtol(value, &end, 10);
    if (end == value || *end != '\0' || v < 1 || v > 64) {
        fprintf(stderr, "mcstats: --%s takes a whole number from 1 to 64, got '%s'\n",
                options[k].name, value);
        return false;
    }
    *(k == OPT_P ? &o->p : &o->s) = (int)v;
    return true;
}

/* Adds render img, the count-th (from 1), into the running means and sums of squared
 * deviations of ref (Welford's update, in doubles in sum2), in both spaces; false
 * (reported) when a value is not finite. */
static bool add_render(McRef *ref, double *sum2, const Image *img, int count, const char *path)
{
    long n = 3L * img->width * img->height;
    for (long k = 0; k < n; k++) {
        double x = img->pixels[k];
        if (!isfinite(x)) {
            fprintf(stderr, "mcstats: %s: pixel %ld is not finite\n", path, k / 3);
            return false;
        }
        double code = image_encode_8bit(x, PNG_ENCODING_SRGB), value[2] = {x, code};
        for (int space = 0; space < 2; space++) {
            float *mean = ref->plane[space == 0 ? MCREF_MEAN : MCREF_CODE];
            double old = mean[k], now = old + (value[space] - old) / count;
            sum2[2 * k + space] += (value[space] - old) * (value[space] - now);
            mean[k] = (float)now;
        }
    }
    return true;
}

/* Runs mcstats: exit status 0 when the reference was written, 2 otherwise. */
int main(int argc, char **argv)
{
    StatsOptions o = {.p = 1, .s = 1, .seeds = ""};
    if (!toolopt_parse("mcstats", options, sizeof options[0], OPTION_COUNT, argc, argv, set_option,
                       &o))
        return 2;
    if (o.help) {
        printf("Usage: mcstats [options] OUT.exr RENDER...\n"
               "Writes the statistical reference of a Monte Carlo render to OUT.exr: per pixel,\n"
               "the mean and the variance of the RENDERs (PFM or EXR, each with its own seed),\n"
               "linear and as 8-bit sRGB code values (docs/grading.md).\n\nOptions:\n");
        toolopt_print(stdout, options, sizeof options[0], OPTION_COUNT);
        return 0;
    }
    int renders = argc - optind - 1;
    if (renders < 2) {
        fprintf(stderr, "mcstats: give the output and two renders at least\n");
        return 2;
    }
    const char *out = argv[optind];
    McRef ref = {0};
    double *sum2 = NULL;
    Error err;
    bool ok = true;
    for (int r = 0; ok && r < renders; r++) {
        const char *path = argv[optind + 1 + r];
        Image img;
        if (image_format_for_path(path) == IMAGE_FORMAT_PNG) {
            fprintf(stderr, "mcstats: %s: a PNG is clamped and rounded: give linear renders\n",
                    path);
            ok = false;
            break;
        }
        if (!image_read(&img, path, &err)) {
            fprintf(stderr, "mcstats: cannot read '%s': %s\n", path, err.text);
            ok = false;
            break;
        }
        if (r == 0) {
            ok = mcref_init(&ref, img.width, img.height) &&
                 (sum2 = calloc(6 * (size_t)img.width * img.height, sizeof *sum2)) != NULL;
            if (!ok)
                fprintf(stderr, "mcstats: out of memory\n");
        } else if (img.width != ref.width || img.height != ref.height) {
            fprintf(stderr, "mcstats: %s is %d x %d, the first render %d x %d\n", path, img.width,
                    img.height, ref.width, ref.height);
            ok = false;
        }
        ok = ok && add_render(&ref, sum2, &img, r + 1, path);
        image_free(&img);
    }
    if (ok) {
        /* The unbiased sample variance of one render, in each space. */
        for (long k = 0; k < 3L * ref.width * ref.height; k++) {
            ref.plane[MCREF_VAR][k] = (float)(sum2[2 * k] / (renders - 1));
            ref.plane[MCREF_CODE_VAR][k] = (float)(sum2[2 * k + 1] / (renders - 1));
        }
        ref.p = o.p, ref.s = o.s, ref.mean_samples = ref.variance_samples = renders;
        snprintf(ref.seeds, sizeof ref.seeds, "%s", o.seeds);
        ok = mcref_write(&ref, out, &err);
        if (!ok)
            fprintf(stderr, "mcstats: cannot write '%s': %s\n", out, err.text);
    }
    free(sum2);
    mcref_free(&ref);
    return ok ? 0 : 2;
}
