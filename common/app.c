/* app.c: the steps of a render from the command line to the image file, shared by every part. */
#include "app.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "explain.h"
#include "hint.h"
#include "image.h"
#include "outfile.h"
#include "stop.h"

enum { EXIT_USAGE = 2 };

/* A --trace-pixel that would print more lines than this is refused: nobody reads them
 * (at P = S = 64, 17 million lines, 1.5 GB), and tracing one sample (@K) says as much. */
#define TRACE_MAX_LINES 1000000.0

/* Says that the run was interrupted and that output (if any: --trace-pixel writes none)
 * was not written; returns the exit status, 128 + the signal's number. */
static int interrupted(const char *output)
{
    if (output != NULL)
        fprintf(stderr, "raytra: interrupted; '%s' was not written\n", output);
    else
        fprintf(stderr, "raytra: interrupted\n");
    return 128 + stop_signal();
}

/* Ends the process at once after a stop, when threads given up by the render loop still
 * use the scene and the image: nothing is freed, flushed or written (no file of the image
 * exists yet, and standard error is unbuffered), so nothing they use disappears. */
static _Noreturn void give_up(const char *output, const char *what)
{
    fprintf(stderr, "raytra: note: stopped without waiting for %s to finish\n", what);
    _exit(interrupted(output));
}

/* Tells the user, once, which parts of the scene this part of the course does not use. */
static void note_ignored(const Program *program, const Scene *scene)
{
    unsigned ignored = scene_features(scene) & ~program->features;
    if (ignored == 0)
        return;
    char list[512] = "";
    for (int k = 0; k < FEATURE_COUNT; k++)
        if (ignored & (1u << k)) {
            ignored &= ~(1u << k);
            size_t used = strlen(list);
            snprintf(list + used, sizeof list - used, "%s%s",
                     used == 0      ? ""
                     : ignored == 0 ? " and "
                                    : ", ",
                     scene_feature_name(1u << k));
        }
    fprintf(stderr,
            "raytra: note: part %s does not use this scene's %s (read and checked, "
            "but ignored)\n",
            program->cli.part, list);
}

/* Multiplies the camera's pixel counts by opts->scale; false (reported) when too large. */
static bool apply_scale(Scene *scene, const Options *opts)
{
    CameraSpec *c = &scene->camera;
    if (opts->scale != 1.0) {
        double nx = fmax(1.0, round(c->nx * opts->scale));
        double ny = fmax(1.0, round(c->ny * opts->scale));
        if (!image_size_ok(nx > IMAGE_MAX_SIDE ? IMAGE_MAX_SIDE + 1L : (long)nx,
                           ny > IMAGE_MAX_SIDE ? IMAGE_MAX_SIDE + 1L : (long)ny)) {
            fprintf(stderr, "raytra: --scale %g makes the image %.0f x %.0f pixels: too large\n",
                    opts->scale, nx, ny);
            return false;
        }
        c->nx = (int)nx;
        c->ny = (int)ny;
    }
    return true;
}

/* Writes img to path through a temporary file, unless a stop was requested meanwhile. */
static bool write_image(const Image *img, const char *path, const Options *opts)
{
    Error err;
    PngEncoding enc = opts->linear ? PNG_ENCODING_LINEAR : PNG_ENCODING_SRGB;
    if (!image_write(img, path, enc, &err)) {
        if (stop_requested())
            return false;
        fprintf(stderr, "raytra: cannot write '%s': %s\n", path, err.text);
        return false;
    }
    return true;
}

/* Prints "raytra: wrote out.png (640 x 480) in 1.2 s with 2 threads: 307200 rays, 256 k rays/s". */
static void print_summary(const char *path, const Image *img, const Options *opts,
                          const RenderResult *r)
{
    unsigned long long total = render_total_rays(&r->stats);
    fprintf(stderr, "raytra: wrote %s (%d x %d) in %.2f s with %d thread%s: %llu rays", path,
            img->width, img->height, r->seconds, opts->threads, opts->threads == 1 ? "" : "s",
            total);
    if (total != r->stats.rays[RAY_PRIMARY]) {
        const char *sep = " (";
        for (int k = 0; k < RAY_KIND_COUNT; k++)
            if (r->stats.rays[k] > 0) {
                fprintf(stderr, "%s%llu %s", sep, r->stats.rays[k],
                        render_ray_kind_name((RayKind)k));
                sep = ", ";
            }
        fputc(')', stderr);
    }
    if (r->seconds > 0)
        fprintf(stderr, ", %.3g M rays/s", (double)total / r->seconds / 1e6);
    fputc('\n', stderr);
}

/* Tells whether the image would be written over a file the scene was read from (the scene
 * file or a mesh), under whatever name, link or spelling; reports it then. */
static bool output_is_input(const Scene *scene, const char *output, const char *scene_path)
{
    for (int k = 0; k < scene->file_count; k++) {
        const FileId *id = &scene->files[k];
        if (!input_same_file(id, output))
            continue;
        if (strcmp(id->path, scene_path) == 0)
            fprintf(stderr,
                    "raytra: cannot write '%s': it is the scene file '%s' itself; give the "
                    "image another name\n",
                    output, scene_path);
        else
            fprintf(stderr,
                    "raytra: cannot write '%s': it is the mesh '%s' that the scene reads; give "
                    "the image another name\n",
                    output, id->path);
        return true;
    }
    return false;
}

/* Loads the scene and prints what it holds: raytra --check. */
static bool check_scene(const Program *program, const Options *opts)
{
    Scene scene;
    SceneLoadOptions load = {opts->convention, opts->convention_given, stderr};
    if (!scene_load(&scene, opts->scene, &load))
        return false;
    const CameraSpec *c = &scene.camera;
#define COUNT(n) (n), (n) == 1 ? "" : "s"
    printf("%s: %d x %d pixels; %d sphere%s, %d plane%s, %d triangle%s (from %d mesh%s and "
           "t lines), %d light%s%s, %d material%s; convention %s\n",
           opts->scene, c->nx, c->ny, COUNT(scene.sphere_count), COUNT(scene.plane_count),
           COUNT(scene.triangle_count), scene.mesh_count, scene.mesh_count == 1 ? "" : "es",
           COUNT(scene.light_count), color_is_black(scene.ambient) ? "" : " and ambient light",
           COUNT(scene.material_count), convention_name(scene.convention));
#undef COUNT
    note_ignored(program, &scene);
    if (opts->view == NULL)
        hint_scene(&scene, program->features, program->cli.part, stderr);
    scene_free(&scene);
    return true;
}

/* Reads the len characters of text, digits alone, as a whole number into *v; false when
 * they are anything else, none, or more than 9 (a number that large is no pixel). */
static bool parse_count(const char *text, size_t len, int *v)
{
    if (len == 0 || len > 9 || strspn(text, "0123456789") < len)
        return false;
    *v = 0;
    for (size_t k = 0; k < len; k++)
        *v = 10 * *v + (text[k] - '0');
    return true;
}

/* Reads "X,Y" into the pixel's column and row, and "X,Y@K" also into *sample, the
 * number of one of the pixel's sample_count samples (-1 when not given); false
 * (reported) when it is not one of the image's pixels, or not one of its samples.
 * sample_count is 0 in a part that traces one ray a pixel. */
static bool parse_pixel(const char *text, const CameraSpec *c, int sample_count, int *x, int *y,
                        int *sample)
{
    const char *at = strchr(text, '@');
    size_t len = at != NULL ? (size_t)(at - text) : strlen(text);
    const char *comma = memchr(text, ',', len);
    *sample = -1;
    if (comma == NULL || !parse_count(text, (size_t)(comma - text), x) ||
        !parse_count(comma + 1, len - (size_t)(comma + 1 - text), y)) {
        fprintf(stderr, "raytra: --trace-pixel takes X,Y (column, row)%s, got '%s'\n",
                sample_count > 0 ? " or X,Y@SAMPLE" : "", text);
        return false;
    }
    if (at != NULL && sample_count == 0) {
        fprintf(stderr,
                "raytra: --trace-pixel %s: this part traces one ray a pixel, through its "
                "centre; @SAMPLE is for a part that samples pixels\n",
                text);
        return false;
    }
    if (at != NULL && (!parse_count(at + 1, strlen(at + 1), sample) || *sample >= sample_count)) {
        fprintf(stderr,
                "raytra: --trace-pixel %s: SAMPLE is the number of one of the pixel's %d "
                "samples, 0 to %d, counted row by row from its bottom-left sub-square\n",
                text, sample_count, sample_count - 1);
        return false;
    }
    if (*x >= c->nx || *y >= c->ny) {
        fprintf(stderr,
                "raytra: --trace-pixel %s is outside the %d x %d image "
                "(columns 0 to %d, rows 0 to %d from the top)\n",
                text, c->nx, c->ny, c->nx - 1, c->ny - 1);
        return false;
    }
    return true;
}

/* What --trace-pixel traces: the pixel (x, y), and with sample >= 0 that one sample. */
typedef struct {
    const Program *program;
    const void *ctx;
    const Scene *scene;
    const Options *opts;
    int x, y, sample;
    int samples; /* the pixel's samples, P x P, where the part samples pixels; 0 elsewhere */
} TraceJob;

/* Traces the one pixel of --trace-pixel, printing its ray tree and its colour before and
 * after clamping and encoding; or, with @SAMPLE, the tree and the colour of that one
 * sample. Row y counts from the top, as in the image; the pixel function's j counts from
 * the bottom, as in the lecture:
 * slide 38 ("relationship of (i, j) th pixel in image plane to u, v").
 * Runs on a render thread (render_call), whose stack holds the deepest path. */
static void trace_one_pixel(void *arg)
{
    const TraceJob *t = arg;
    const Program *program = t->program;
    const Options *opts = t->opts;
    const void *ctx = t->ctx;
    int x = t->x, y = t->y, sample = t->sample;
    const CameraSpec *c = &t->scene->camera;
    int j = c->ny - 1 - y;
    printf("pixel %d,%d of %d x %d (column from the left, row from the top): i = %d, "
           "j = %d counted from the bottom, its centre at image point (%g, %g)\n",
           x, y, c->nx, c->ny, x, j, x + 0.5, j + 0.5);
    RayStats stats = {{0}};
    if (sample >= 0) {
        Color s = program->sample(ctx, x, j, sample, &stats);
        int count = t->samples;
        printf("sample %d: colour (%.9g, %.9g, %.9g); the pixel's colour is the mean of its "
               "%d sample%s\n",
               sample, s.r, s.g, s.b, count, count == 1 ? "" : "s");
        return;
    }
    Color radiance = program->pixel(ctx, x, j, &stats);
    PngEncoding enc = opts->linear ? PNG_ENCODING_LINEAR : PNG_ENCODING_SRGB;
    printf("colour (%.9g, %.9g, %.9g); clamped to [0, 1]: (%.9g, %.9g, %.9g); in a PNG "
           "(%s): (%d, %d, %d)\n",
           radiance.r, radiance.g, radiance.b, fmin(fmax(radiance.r, 0), 1),
           fmin(fmax(radiance.g, 0), 1), fmin(fmax(radiance.b, 0), 1),
           opts->linear ? "linear" : "sRGB", image_encode_8bit(radiance.r, enc),
           image_encode_8bit(radiance.g, enc), image_encode_8bit(radiance.b, enc));
}

/* Tells whether the trace of --trace-pixel is short enough to be read; refuses it (false,
 * reported) when it would print more than TRACE_MAX_LINES lines, and warns when it may.
 * The part estimates the lines (Program.trace_lines): at least fewest, and at most most
 * when every mirror and glass path goes on to the depth limit. */
static bool trace_size_ok(const Program *program, const void *ctx, const Options *opts, int sample,
                          int samples)
{
    double fewest = 0, most = 0;
    if (program->trace_lines != NULL)
        program->trace_lines(ctx, sample, &fewest, &most);
    if (fewest <= TRACE_MAX_LINES && most <= TRACE_MAX_LINES)
        return true;
    char how[200] = "";
    if (samples > 0 && sample < 0)
        snprintf(how, sizeof how,
                 "; trace one of its %d samples with --trace-pixel %s@K (K from 0 to %d), or "
                 "take fewer samples",
                 samples, opts->trace_pixel, samples - 1);
    if (fewest > TRACE_MAX_LINES) {
        fprintf(stderr,
                "raytra: --trace-pixel %s would print at least %.3g million lines, more than "
                "anyone reads: refused%s\n",
                opts->trace_pixel, fewest / 1e6, how);
        return false;
    }
    fprintf(stderr,
            "raytra: warning: --trace-pixel %s may print up to %.3g million lines, when every "
            "mirror and glass path goes on to the depth limit%s\n",
            opts->trace_pixel, most / 1e6, how);
    return true;
}

/* Tells whether the --view asked for, if any, is one this part can draw; says why not. */
static bool view_usable(const Program *program, const Options *opts)
{
    ViewKind kind;
    if (opts->view == NULL)
        return true;
    if (!debugview_from_name(opts->view, &kind)) {
        fprintf(stderr, "raytra: unknown view '%s' (%s)\n", opts->view, debugview_names());
        return false;
    }
    /* A view of what the part does not have (lights, boxes) would be black under a legend
     * that promises counts. */
    const char *lacks = "";
    if (program->probe == NULL) {
        fprintf(stderr, "raytra: part %s cannot draw views\n", program->cli.part);
        return false;
    }
    if (!debugview_drawn_by(kind, program->views, &lacks)) {
        fprintf(stderr,
                "raytra: part %s cannot draw the view '%s': it has no %s yet (a later part "
                "of the course draws it)\n",
                program->cli.part, opts->view, lacks);
        return false;
    }
    return true;
}

/* What --view's pixel function reads: the part's probe and state, and the view. */
typedef struct {
    const Program *program;
    const void *ctx;
    ViewKind kind;
} ViewJob;

/* The pixel function of --view: the colour of what the camera ray meets first. */
static Color view_pixel(const void *ctx, int i, int j, RayStats *stats)
{
    const ViewJob *view = ctx;
    Probe probe = {0};
    view->program->probe(view->ctx, i, j, &probe);
    stats->rays[RAY_PRIMARY]++;
    return debugview_color(view->kind, &probe);
}

/* Renders the scene with the part's pixel function, or the view's, into img; false when
 * stopped (and the process ends at once when pixels under way had to be given up).
 * Pixels that came out NaN or infinite are told loudly: they are a bug, or a scene the
 * parser should have refused. */
static bool render(const Program *program, void *ctx, const Options *opts, const Scene *scene,
                   Image *img, RenderResult *result, const char *output)
{
    ViewJob view = {program, ctx, VIEW_NONE};
    if (opts->view != NULL)
        debugview_from_name(opts->view, &view.kind);
    RenderJob job = {
        .pixel = view.kind != VIEW_NONE ? view_pixel : program->pixel,
        .ctx = view.kind != VIEW_NONE ? (const void *)&view : ctx,
        .threads = opts->threads,
        .progress = !opts->quiet && isatty(STDERR_FILENO),
    };
    render_image(img, &job, result);
    /* Threads given up after a stop still use job, view, ctx and img: never return. */
    if (result->abandoned)
        give_up(output, "the pixels under way");
    if (result->stopped)
        return false;
    if (view.kind != VIEW_NONE)
        debugview_finish(view.kind, img, scene->light_count, stderr);
    if (result->nonfinite > 0)
        fprintf(stderr,
                "raytra: %s: %ld pixel%s came out NaN or infinite (or beyond the range of a "
                "float) and %s written magenta; the first is at column %d, row %d from the "
                "top. This is a bug in raytra, or a scene it should have refused: please "
                "report it\n",
                opts->strict ? "error" : "warning", result->nonfinite,
                result->nonfinite == 1 ? "" : "s", result->nonfinite == 1 ? "was" : "were",
                result->first_nonfinite_x, result->first_nonfinite_y);
    return true;
}

/* Runs a part's program: parse, load, check the output, render, write, summarise. */
int app_main(const Program *program, int argc, char **argv)
{
    Options opts;
    CliResult cli = cli_parse(&program->cli, argc, argv, &opts);
    if (cli != CLI_RUN)
        return cli == CLI_DONE ? EXIT_SUCCESS : EXIT_USAGE;

    if (!view_usable(program, &opts))
        return EXIT_USAGE;
    char *output = opts.output ? strdup(opts.output) : cli_default_output(opts.scene);
    if (output == NULL) {
        fprintf(stderr, "raytra: out of memory\n");
        return EXIT_FAILURE;
    }
    int status = EXIT_FAILURE;
    Error err;
    Scene scene;
    bool loaded = false;
    void *ctx = NULL;
    Image img = {0};
    if (opts.check_only) {
        status = check_scene(program, &opts) ? EXIT_SUCCESS : EXIT_FAILURE;
        goto done;
    }
    /* --trace-pixel writes no image: its output is neither checked nor needed. */
    bool tracing = opts.trace_pixel != NULL;
    if (!tracing && image_format_for_path(output) == IMAGE_FORMAT_UNKNOWN) {
        fprintf(stderr,
                "raytra: cannot write '%s': unknown image format (use .png, .pfm or .exr)\n",
                output);
        status = EXIT_USAGE;
        goto done;
    }
    /* Find out now, not after a long render, that the image cannot be written. */
    if (!tracing && !outfile_check(output, &err)) {
        fprintf(stderr, "raytra: cannot write '%s': %s\n", output, err.text);
        goto done;
    }
    stop_install();
    SceneLoadOptions load = {opts.convention, opts.convention_given, stderr};
    loaded = scene_load(&scene, opts.scene, &load);
    if (!loaded || (!tracing && output_is_input(&scene, output, opts.scene)) ||
        !apply_scale(&scene, &opts))
        goto done;
    note_ignored(program, &scene);
    if (opts.view == NULL && !tracing)
        hint_scene(&scene, program->features, program->cli.part, stderr);
    int trace_x = 0, trace_y = 0, trace_sample = -1;
    Explain explain = {stdout, &scene};
    /* The pixel's samples, where the part samples pixels: the one place this reads them. */
    int side = program->sample != NULL ? cli_int(&opts, program->samples_option) : 0;
    int samples = side * side;
    if (opts.trace_pixel != NULL) {
        if (!parse_pixel(opts.trace_pixel, &scene.camera, samples, &trace_x, &trace_y,
                         &trace_sample)) {
            status = EXIT_USAGE;
            goto done;
        }
        opts.explain = &explain;
    }
    if (program->setup != NULL && !program->setup(&scene, &opts, &ctx))
        goto done;
    if (tracing && !trace_size_ok(program, ctx, &opts, trace_sample, samples)) {
        status = EXIT_USAGE;
        goto done;
    }
    if (tracing) {
        TraceJob trace = {program, ctx, &scene, &opts, trace_x, trace_y, trace_sample, samples};
        /* A trace given up after a stop still prints from the scene: never return. */
        if (!render_call(trace_one_pixel, &trace))
            give_up(NULL, "the trace");
        status = EXIT_SUCCESS;
        goto done;
    }
    if (!image_init(&img, scene.camera.nx, scene.camera.ny)) {
        fprintf(stderr, "raytra: not enough memory for a %d x %d image\n", scene.camera.nx,
                scene.camera.ny);
        goto done;
    }
    RenderResult result;
    if (render(program, ctx, &opts, &scene, &img, &result, output) &&
        write_image(&img, output, &opts)) {
        /* Under --strict a non-finite pixel fails the run, but the image is still written
         * so that its magenta pixels show where the bug is. */
        status = opts.strict && result.nonfinite > 0 ? EXIT_FAILURE : EXIT_SUCCESS;
        if (opts.view == NULL)
            hint_image(&scene, program->features, &img, stderr);
        if (!opts.quiet) {
            print_summary(output, &img, &opts, &result);
            if (program->report != NULL)
                program->report(ctx);
        }
    }
done:
    if (stop_requested())
        status = interrupted(opts.trace_pixel != NULL ? NULL : output);
    image_free(&img);
    if (program->cleanup != NULL && ctx != NULL)
        program->cleanup(ctx);
    if (loaded)
        scene_free(&scene);
    free(output);
    return status;
}
