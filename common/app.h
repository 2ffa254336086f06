/* app.h: the program every part builds: command line, scene, render, image file, summary. */
#ifndef RAYTRA_APP_H
#define RAYTRA_APP_H

#include <stdbool.h>

#include "cli.h"
#include "debugview.h"
#include "render.h"
#include "scene.h"

/* What a part plugs into the shared program. */
typedef struct {
    CliSpec cli;
    unsigned features; /* FEATURE_ bits the part renders; the rest is reported as ignored */
    /* Builds the state pixel reads from the loaded scene; false (reported) on failure. */
    bool (*setup)(const Scene *scene, const Options *opts, void **ctx);
    PixelFn pixel;
    /* The radiance of sample k alone of pixel (i, j), with the rays and random numbers
     * it has in pixel's mean: --trace-pixel X,Y@K. NULL when the part traces one ray a
     * pixel; a part that sets it names the option of P, its P x P samples a pixel. */
    Color (*sample)(const void *ctx, int i, int j, int k, RayStats *stats);
    const char *samples_option;
    /* Tells what a pixel's camera ray meets first, for --view; NULL if the part cannot. */
    ProbeFn probe;
    unsigned views; /* the views it draws beyond every part's: 1 << VIEW_LIGHT_COUNT, ... */
    /* Estimates how many lines --trace-pixel prints for a pixel (sample < 0) or one of
     * its samples: at least *fewest, at most *most; NULL when a trace is a few lines. */
    void (*trace_lines)(const void *ctx, int sample, double *fewest, double *most);
    /* Prints part-specific figures after the summary line; may be NULL. */
    void (*report)(const void *ctx);
    void (*cleanup)(void *ctx);
} Program;

int app_main(const Program *program, int argc, char **argv);

#endif
