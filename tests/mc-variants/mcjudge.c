/* mcjudge.c: judges many renders of one scene against its statistical reference at once, each
 * as the PNG, PFM and EXR raytra would write of it, for the calibration (calibrate.sh). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "image.h"
#include "image_read.h"
#include "mcref.h"
#include "statdiff.h"

/* The formats a render is judged in, as the file names' endings say them; the last, a
 * PNG written by truncation, only when asked (--truncate). */
static const char *const formats[] = {"png", "pfm", "exr", "png"};
static const char *const labels[] = {"png", "pfm", "exr", "png-trunc"};

/* Writes img as the file raytra would write in format f (through path), reads it back into
 * out, as a grader would; the fourth format a PNG whose codes are truncated, not rounded
 * (as a student's writer may); false (reported) when it cannot. */
static bool as_written(const Image *img, int f, const char *dir, Image *out)
{
    char path[4096];
    Error err;
    snprintf(path, sizeof path, "%s/mcjudge-%ld.%s", dir, (long)getpid(), formats[f]);
    Image cut = {0};
    bool truncate = f == 3;
    if (truncate && image_init(&cut, img->width, img->height)) {
        /* Each value moved to the code it truncates to, which rounding then keeps. */
        for (long k = 0; k < 3L * img->width * img->height; k++) {
            double v = img->pixels[k] < 0 ? 0 : img->pixels[k] > 1 ? 1 : img->pixels[k];
            cut.pixels[k] = (float)image_srgb_decode(floor(255 * image_srgb_encode(v)) / 255);
        }
        img = &cut;
    }
    bool ok = image_write(img, path, PNG_ENCODING_SRGB, &err) && image_read(out, path, &err);
    image_free(&cut);
    if (!ok)
        fprintf(stderr, "mcjudge: %s: %s\n", path, err.text);
    remove(path);
    return ok;
}

/* Writes the reference's mean, the converged image, to path: the "image" a student would
 * hand in who copied it out of NAME.stats.exr. */
static int write_mean(const char *reference, const char *path)
{
    McRef ref;
    Image img;
    Error err;
    if (!mcref_read(&ref, reference, &err) || !image_init(&img, ref.width, ref.height)) {
        fprintf(stderr, "mcjudge: cannot read '%s'\n", reference);
        return 2;
    }
    memcpy(img.pixels, ref.plane[MCREF_MEAN], 3 * sizeof(float) * ref.width * ref.height);
    bool ok = image_write(&img, path, PNG_ENCODING_SRGB, &err);
    if (!ok)
        fprintf(stderr, "mcjudge: cannot write '%s': %s\n", path, err.text);
    image_free(&img);
    mcref_free(&ref);
    return ok ? 0 : 2;
}

/* Runs mcjudge: mcjudge [--ok] [--truncate] REF.stats.exr RENDER.pfm... prints a line a
 * render and format (with --truncate, a PNG written by truncation too): NAME FORMAT
 * PASS|FAIL TEST Z_FRACTION NOISE_IMAGE NOISE_BLOCK EXACT_DIFFER; mcjudge --mean
 * REF.stats.exr OUT writes the reference's mean. */
int main(int argc, char **argv)
{
    StatStandard standard = STATDIFF_GOOD;
    int at = 1;
    if (argc == 4 && strcmp(argv[1], "--mean") == 0)
        return write_mean(argv[2], argv[3]);
    bool truncate = false;
    for (; at < argc && argv[at][0] == '-'; at++)
        if (strcmp(argv[at], "--ok") == 0)
            standard = STATDIFF_OK;
        else if (strcmp(argv[at], "--truncate") == 0)
            truncate = true;
        else
            break;
    if (argc - at < 2) {
        fprintf(stderr, "usage: mcjudge [--ok] [--truncate] REF.stats.exr RENDER.pfm...\n"
                        "       mcjudge --mean REF.stats.exr OUT\n");
        return 2;
    }
    const char *dir = getenv("TMPDIR") != NULL ? getenv("TMPDIR") : "/tmp";
    McRef ref;
    Error err;
    if (!mcref_read(&ref, argv[at], &err)) {
        fprintf(stderr, "mcjudge: cannot read '%s': %s\n", argv[at], err.text);
        return 2;
    }
    int status = 0;
    for (int k = at + 1; k < argc && status == 0; k++) {
        Image render;
        if (!image_read(&render, argv[k], &err)) {
            fprintf(stderr, "mcjudge: cannot read '%s': %s\n", argv[k], err.text);
            status = 2;
            break;
        }
        for (int f = 0; f < (truncate ? 4 : 3) && status == 0; f++) {
            Image img;
            StatVerdict v;
            if (!as_written(&render, f, dir, &img)) {
                status = 2;
                break;
            }
            if (!statdiff_judge(&ref, &img, f == 0 || f == 3, standard, &v))
                status = 2;
            else
                printf("%s %s %s %s %.4f %.4f %.4f %d\n", argv[k], labels[f],
                       v.pass ? "PASS" : "FAIL", v.pass ? "-" : v.test, v.z_fraction, v.noise_image,
                       v.noise_block, v.exact_differ);
            image_free(&img);
        }
        image_free(&render);
    }
    mcref_free(&ref);
    return status;
}
