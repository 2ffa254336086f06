/* grade_judge.c: an image judged against its reference through imgdiff: its verdict, its reason, its figures. */
#include "grade_judge.h"

#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "grade_base.h"
#include "grade_diagnose.h"
#include "grade_path.h"
#include "grade_run.h"
#include "grade_verdict.h"
#include "image_read.h"
#include "imgfile.h"

/* Returns the path of submission s's image of render k: where its program writes it, or in a
 * folder of images the file named as the reference, or with another of .png, .pfm and .exr. */
char *judge_image_path(const Grading *g, const Submission *s, int k)
{
    static const char *const endings[] = {".png", ".pfm", ".exr"};
    const Render *r = &g->renders[k];
    if (s->program)
        return grade_format("%s/images/%s", s->work, r->image);
    char *found = grade_format("%s/%s", s->path, r->image);
    struct stat st;
    for (size_t e = 0; e < sizeof endings / sizeof *endings && lstat(found, &st) != 0; e++)
        found = grade_format("%s/%s%s", s->path, r->name, endings[e]);
    return found;
}

/* Tells whether the images at a and b, of any format, hold the same values pixel for pixel. */
static bool same_pixels(const char *a, const char *b)
{
    Image ia = {0}, ib = {0};
    Error err;
    bool same = image_read(&ia, a, &err) && image_read(&ib, b, &err) &&
                ia.width == ib.width && ia.height == ib.height &&
                memcmp(ia.pixels, ib.pixels, 3 * sizeof *ia.pixels * (size_t)ia.width *
                                                 (size_t)ia.height) == 0;
    image_free(&ia);
    image_free(&ib);
    return same;
}

/* What one run of imgdiff said beyond the figures: its verdict, and its words. */
typedef struct {
    RunResult run;
    char *reason;      /* why it could not compare, or NULL */
    char *statistical; /* a statistical comparison's reason, or NULL */
    int size[4]; /* the reference's width and height, then the image's, when they differ */
} DiffRun;

/* Runs imgdiff on image, submitted for render k, against the file `against` with the
 * options `how` (NULL-ended), writing the full-size heat map and the thumbnails the report
 * shows, and reads its --machine lines (docs/grading.md lists them) into res->figures. */
static DiffRun run_imgdiff(const Grading *g, const Submission *s, int k, const char *image,
                           const char *against, char *const how[])
{
    const Render *r = &g->renders[k];
    SceneResult *res = &s->results[k];
    Figures *f = &res->figures;
    char *argv[26] = {g->imgdiff, "--machine", "--threshold", (char *)g->threshold, "--allow",
                      (char *)g->allow, "--standard", (char *)g->standard, "--diff",
                      grade_format("%s/%s.heat.png", s->work, r->name), "--thumb",
                      res->image_show, "--diff-thumb", res->heat_show};
    int n = 14;
    while (*how != NULL && n < 22)
        argv[n++] = *how++;
    argv[n++] = "--";
    argv[n++] = (char *)against;
    argv[n] = (char *)image;
    DiffRun d = {.run = run_program(argv, NULL, grade_format("%s/%s.diff.txt", s->work, r->name),
                                    600, RUN_OWN_MEMORY(g->memory_limit))};
    *f = (Figures){0};
    FILE *in = fmemopen(d.run.output, strlen(d.run.output) + 1, "r");
    char line[1024];
    while (in != NULL && fgets(line, sizeof line, in) != NULL) {
        line[strcspn(line, "\n")] = '\0';
        const char *named = strstr(line, "': "); /* imgdiff: cannot read 'FILE': REASON */
        if (strncmp(line, "reason ", 7) == 0) /* a statistical comparison says why */
            d.statistical = grade_format("%s", line + 7);
        if (d.reason == NULL && strncmp(line, "imgdiff: ", 9) == 0)
            d.reason = grade_format("%s", named != NULL ? named + 3 : line + 9);
        /* || stops at the first pattern that fits the line. */
        (void)(sscanf(line, "sizes %d %d %d %d", d.size, d.size + 1, d.size + 2, d.size + 3) == 4 ||
               sscanf(line, "box %d %d %d %d", f->box, f->box + 1, f->box + 2, f->box + 3) == 4 ||
               sscanf(line, "threshold %lf", &f->threshold) == 1 ||
               sscanf(line, "allow %lf", &f->allow) == 1 ||
               sscanf(line, "max %lf %lf %lf", &f->max[0], &f->max[1], &f->max[2]) == 3 ||
               sscanf(line, "mean %lf", &f->mean) == 1 ||
               sscanf(line, "rmse %lf", &f->rmse) == 1 ||
               sscanf(line, "psnr %lf", &f->psnr) == 1 ||
               sscanf(line, "differing %ld %ld", &f->differing, &f->pixels) == 2 ||
               sscanf(line, "heat_scale %lf", &f->heat_scale) == 1 ||
               sscanf(line, "bias_worst %lf %lf", &f->bias_z, &f->bias_critical) == 2 ||
               sscanf(line, "noise_image %lf %lf %lf", &f->noise, &f->noise_low,
                      &f->noise_high) == 3 ||
               sscanf(line, "exact %ld", &f->exact) == 1);
    }
    if (in != NULL)
        fclose(in);
    /* imgdiff's exit status: 0 when the images match, 1 when not, 2 on trouble */
    res->compared = d.run.end == RUN_EXITED && d.run.status <= 1;
    return d;
}

/* Compares image, submitted for render k, with the reference through imgdiff (run_imgdiff);
 * sets the verdict, with the reason in words. IMAGE=OTHER must then also equal the
 * program's own image of OTHER, pixel for pixel; IMAGE>MASK is judged by coverage of MASK
 * alone (docs/grading.md). */
static void compare_image(const Grading *g, const Submission *s, int k, const char *image)
{
    const Render *r = &g->renders[k];
    SceneResult *res = &s->results[k];
    Figures *f = &res->figures;
    res->image_show = grade_format("%s/%s.show.png", s->work, r->name);
    res->heat_show = grade_format("%s/%s.heat-show.png", s->work, r->name);
    const Render *other = r->judge == JUDGE_SAME_AS ? &g->renders[r->same_as] : NULL;
    if (other != NULL && !s->results[r->same_as].compared) {
        verdict_set(res, VERDICT_ERROR,
                    "not judged: it must equal this program's own %s, which could not be "
                    "compared (%s)",
                    other->image, verdict_info[s->results[r->same_as].verdict].name);
        return;
    }
    static char *const plain[] = {NULL}, *const cover[] = {"--cover", NULL},
                       *const exact[] = {"--threshold", "0", "--allow", "0", NULL};
    DiffRun d = run_imgdiff(g, s, k, image, r->judge == JUDGE_COVER ? r->mask : r->reference,
                            r->judge == JUDGE_COVER ? cover : plain);
    Verdict v = d.run.ok ? VERDICT_PASS : VERDICT_FAIL;
    /* Identical to the reference: the report then shows the reference's picture. */
    res->identical = res->compared && r->judge != JUDGE_COVER && f->max[0] == 0 &&
                     f->max[1] == 0 && f->max[2] == 0;
    /* A program writes the reference's values when it renders as the model answer does, and
     * the canary's when it copies the file it found in its folder; images handed in are
     * flagged when they are the reference's file. */
    res->copy = s->program ? res->compared && r->canary != NULL && same_pixels(image, r->canary)
                           : ((res->identical || d.statistical != NULL) &&
                              path_same_bytes(image, r->reference)) ||
                                 (r->shipped != NULL && path_same_bytes(image, r->shipped));
    /* It matches the reference: now against the program's own OTHER, exactly. */
    bool same = other != NULL && v == VERDICT_PASS;
    if (same) {
        d = run_imgdiff(g, s, k, image, judge_image_path(g, s, r->same_as), exact);
        v = d.run.ok ? VERDICT_PASS : VERDICT_FAIL;
        res->identical = res->copy = false;
    }
    const char *why = r->why != NULL ? r->why : "", *colon = r->why != NULL ? ": " : "";
    if (res->compared && same && v == VERDICT_FAIL)
        verdict_set(res, v,
                    "%ld pixels (%.3g%%) differ from this program's own %s; the two must be "
                    "equal pixel for pixel%s%s",
                    f->differing, 100.0 * f->differing / f->pixels, other->image, colon, why);
    else if (res->compared && same)
        verdict_set(res, v, "matches the reference, and equals this program's own %s pixel for "
                    "pixel", other->image);
    else if (res->compared && r->judge == JUDGE_COVER)
        verdict_set(res, v,
                    "%.3g%% of the pixels are black here and drawn in %s, %s the %.3g%% "
                    "allowed%s%s",
                    100.0 * f->differing / f->pixels, strrchr(r->mask, '/') + 1,
                    v == VERDICT_PASS ? "within" : "more than", f->allow * 100,
                    v == VERDICT_PASS ? "" : colon, v == VERDICT_PASS ? "" : why);
    else if (res->compared && d.statistical != NULL)
        verdict_set(res, v, "%s", d.statistical);
    else if (res->identical)
        verdict_set(res, v, "identical to the reference");
    else if (res->compared && f->differing == 0)
        verdict_set(res, v, "no pixel differs by more than %.3g/255", f->threshold * 255);
    else if (res->compared)
        verdict_set(res, v,
                    "%.3g%% of the pixels differ by more than %.3g/255, %s the %.3g%% allowed",
                    100.0 * f->differing / f->pixels, f->threshold * 255,
                    v == VERDICT_PASS ? "within" : "more than", f->allow * 100);
    else if (d.size[0] > 0) {
        verdict_set(res, VERDICT_WRONG_SIZE, "the image is %d x %d pixels, the reference %d x %d",
                    d.size[2], d.size[3], d.size[0], d.size[1]);
        res->relative_width = (double)d.size[2] / d.size[0];
    } else if (d.reason != NULL)
        verdict_set(res, VERDICT_UNREADABLE, "the file cannot be read as an image: %s", d.reason);
    else if (d.run.end != RUN_INTERRUPTED)
        verdict_set(res, VERDICT_UNREADABLE, "imgdiff could not compare the file (%s)",
                    run_describe(&d.run));
    diagnose_scene(g, s, k, other != NULL ? judge_image_path(g, s, r->same_as) : image);
}

/* Judges the file at path as the image of render k, with lstat first so that a FIFO or a
 * device is never opened: MISSING (saying `missing`), LINK, UNREADABLE, or compared. */
void judge_file(const Grading *g, const Submission *s, int k, const char *path,
                const char *missing)
{
    SceneResult *res = &s->results[k];
    struct stat st, ref;
    const char *name = strrchr(path, '/') + 1;
    char target[256] = "";
    if (lstat(path, &st) != 0)
        verdict_set(res, VERDICT_MISSING, "%s", missing);
    else if (S_ISLNK(st.st_mode) && readlink(path, target, sizeof target - 1) >= 0)
        verdict_set(res, VERDICT_LINK, "%s is a symbolic link to %s: not an image handed in", name,
                    target);
    else if (!S_ISREG(st.st_mode))
        verdict_set(res, VERDICT_UNREADABLE, "%s is not a regular file (%s)", name,
                    imgfile_kind_text(st.st_mode));
    else if ((stat(g->renders[k].reference, &ref) == 0 && ref.st_dev == st.st_dev &&
              ref.st_ino == st.st_ino) ||
             (g->renders[k].shipped != NULL && stat(g->renders[k].shipped, &ref) == 0 && ref.st_dev == st.st_dev &&
              ref.st_ino == st.st_ino))
        verdict_set(res, VERDICT_LINK, "%s is a hard link to the reference image", name);
    else
        compare_image(g, s, k, path);
}
