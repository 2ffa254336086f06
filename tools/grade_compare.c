/* grade_compare.c: judging a submitted image: a file handed in, compared by imgdiff. */
#include "grade_compare.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "grade_run.h"
#include "grade_thumb.h"
#include "imgfile.h"

/* What imgdiff --machine said about an image against its reference. */
typedef struct {
    Figures figures;
    bool has_verdict, pass;
    bool has_sizes;
    int sizes[4];     /* the reference's width and height, then the image's */
    char reason[400]; /* imgdiff's complaint, when it made one */
} DiffAnswer;

/* Reads a line of imgdiff's figures into fig, if it is one; psnr may be "inf". */
static void read_figure(const char *line, Figures *fig)
{
    /* || stops at the first pattern that fits the line. */
    (void)(sscanf(line, "threshold %lf", &fig->threshold) == 1 ||
           sscanf(line, "allow %lf", &fig->allow) == 1 ||
           sscanf(line, "max %lf %lf %lf", &fig->max[0], &fig->max[1], &fig->max[2]) == 3 ||
           sscanf(line, "mean %lf", &fig->mean) == 1 || sscanf(line, "rmse %lf", &fig->rmse) == 1 ||
           sscanf(line, "psnr %lf", &fig->psnr) == 1 ||
           sscanf(line, "differing %ld %ld", &fig->differing, &fig->pixels) == 2 ||
           sscanf(line, "heat_scale %lf", &fig->heat_scale) == 1);
}

/* Reads what imgdiff --machine wrote (its log, stdout and stderr) into a; image is the
 * compared image's path, left out of imgdiff's complaint about it. */
static void read_answer(const char *log, const char *image, DiffAnswer *a)
{
    *a = (DiffAnswer){0};
    FILE *f = imgfile_fopen(log);
    if (f == NULL)
        return;
    Figures *fig = &a->figures;
    char line[1024], word[16];
    char *cannot = grade_format("imgdiff: cannot read '%s': ", image);
    while (fgets(line, sizeof line, f) != NULL) {
        line[strcspn(line, "\n")] = '\0';
        if (sscanf(line, "verdict %15s", word) == 1) {
            a->has_verdict = true;
            a->pass = strcmp(word, "PASS") == 0;
        } else if (sscanf(line, "sizes %d %d %d %d", &a->sizes[0], &a->sizes[1], &a->sizes[2],
                          &a->sizes[3]) == 4) {
            a->has_sizes = true;
        } else if (sscanf(line, "box %d %d %d %d", &fig->box[0], &fig->box[1], &fig->box[2],
                          &fig->box[3]) == 4) {
            fig->has_box = true;
        } else if (strncmp(line, cannot, strlen(cannot)) == 0 && a->reason[0] == '\0') {
            snprintf(a->reason, sizeof a->reason, "%.*s", (int)sizeof a->reason - 1,
                     line + strlen(cannot));
        } else if (strncmp(line, "imgdiff: ", 9) == 0 && a->reason[0] == '\0') {
            snprintf(a->reason, sizeof a->reason, "%.*s", (int)sizeof a->reason - 1, line + 9);
        } else {
            read_figure(line, fig);
        }
    }
    free(cannot);
    fclose(f);
}

/* Sets the verdict PASS or FAIL from imgdiff's figures, with the reason in words. */
static void judge_figures(SceneResult *res, const DiffAnswer *a)
{
    const Figures *f = &a->figures;
    Verdict v = a->pass ? VERDICT_PASS : VERDICT_FAIL;
    double percent = f->pixels > 0 ? 100.0 * f->differing / f->pixels : 0;
    res->compared = true;
    res->figures = *f;
    res->identical = f->max[0] == 0 && f->max[1] == 0 && f->max[2] == 0;
    if (res->identical)
        grade_verdict(res, v, "identical to the reference");
    else if (f->differing == 0)
        grade_verdict(res, v, "no pixel differs by more than %.3g/255", f->threshold * 255);
    else
        grade_verdict(
            res, v, "%.3g%% of the pixels differ by more than %.3g/255, %s the %.3g%% allowed",
            percent, f->threshold * 255, a->pass ? "within" : "more than", f->allow * 100);
}

/* Compares image, submitted for render k, with the reference through imgdiff, and makes
 * the thumbnails the report shows. */
void compare_image(const Grading *g, const Submission *s, int k, const char *image)
{
    const Render *r = &g->renders[k];
    SceneResult *res = &s->results[k];
    char *log = grade_format("%s/%s.diff.txt", s->work, r->name);
    char *heat = grade_format("%s/%s.heat.png", s->work, r->name);
    char *argv[] = {g->imgdiff, "--machine",          "--threshold", (char *)g->threshold,
                    "--allow",  (char *)g->allow,     "--diff",      heat,
                    "--",       (char *)r->reference, (char *)image, NULL};
    RunSpec spec = {.log = log, .time_limit = 600, .memory_limit = RUN_OWN_MEMORY(g->memory_limit)};
    RunResult run = run_program(argv, &spec);
    DiffAnswer a;
    read_answer(log, image, &a);
    char how[200];
    run_describe(&run, spec.time_limit, how, sizeof how);
    if (run.end == RUN_EXITED && run.status <= 1 && a.has_verdict)
        judge_figures(res, &a);
    else if (run.end == RUN_EXITED && a.has_sizes) {
        grade_verdict(res, VERDICT_WRONG_SIZE, "the image is %d x %d pixels, the reference %d x %d",
                      a.sizes[2], a.sizes[3], a.sizes[0], a.sizes[1]);
        res->relative_width = a.sizes[0] > 0 ? (double)a.sizes[2] / a.sizes[0] : 0;
    } else if (run.end == RUN_EXITED && a.reason[0] != '\0')
        grade_verdict(res, VERDICT_UNREADABLE, "the file cannot be read as an image: %s", a.reason);
    else if (run.end != RUN_INTERRUPTED)
        grade_verdict(res, VERDICT_UNREADABLE, "imgdiff could not compare the file (%s)", how);
    if (res->verdict == VERDICT_UNREADABLE || run.end == RUN_INTERRUPTED || res->identical)
        goto done;
    char *show = grade_format("%s/%s.show.png", s->work, r->name);
    char *heat_show = grade_format("%s/%s.heat-show.png", s->work, r->name);
    if (thumb_make(image, show, THUMB_SIDE, THUMB_MEAN, NULL, g->memory_limit))
        res->image_show = grade_copy(show);
    if (res->compared &&
        thumb_make(heat, heat_show, THUMB_SIDE, THUMB_PEAKS, NULL, g->memory_limit))
        res->heat_show = grade_copy(heat_show);
    free(show);
    free(heat_show);
done:
    free(heat);
    free(log);
}

/* Tells whether the file at path, found for render r, is an image handed in: a regular
 * file, not a symbolic link (to a reference, to a classmate's folder) nor the reference
 * itself under another name; else sets the verdict, LINK or UNREADABLE. lstat only: a
 * FIFO or a device is never opened. */
bool compare_handed_in(const Render *r, SceneResult *res, const char *path)
{
    struct stat st, ref;
    const char *name = strrchr(path, '/') + 1;
    char target[256] = "";
    if (lstat(path, &st) != 0) {
        grade_verdict(res, VERDICT_UNREADABLE, "%s cannot be read: %s", name, strerror(errno));
    } else if (S_ISLNK(st.st_mode)) {
        ssize_t n = readlink(path, target, sizeof target - 1);
        target[n > 0 ? n : 0] = '\0';
        grade_verdict(res, VERDICT_LINK, "%s is a symbolic link to %s: not an image handed in",
                      name, target);
    } else if (!S_ISREG(st.st_mode)) {
        grade_verdict(res, VERDICT_UNREADABLE, "%s is not a regular file (%s)", name,
                      S_ISFIFO(st.st_mode)  ? "a FIFO"
                      : S_ISDIR(st.st_mode) ? "a folder"
                                            : "a special file");
    } else if (stat(r->reference, &ref) == 0 && ref.st_dev == st.st_dev &&
               ref.st_ino == st.st_ino) {
        grade_verdict(res, VERDICT_LINK, "%s is a hard link to the reference image", name);
    } else {
        return true;
    }
    return false;
}
