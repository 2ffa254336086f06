/* grade_compare.c: judging a submitted image: a file handed in, compared by imgdiff, shown. */
#include "grade.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "image.h"
#include "imgfile.h"

/* The largest image shown: a larger one is surely a mistake, or a decompression bomb. */
#define THUMB_MAX_PIXELS (4096L * 4096)

/* What imgdiff --machine said about an image against its reference. */
typedef struct {
    Figures figures;
    bool has_verdict, pass, has_sizes;
    int sizes[4];     /* the reference's width and height, then the image's */
    char reason[400]; /* imgdiff's complaint, when it made one */
} DiffAnswer;

/* One thumbnail to make: a heat map's (peaks) keeps each block's brightest pixel, so that
 * a single differing pixel stays; a picture's, the block's mean. */
typedef struct {
    const char *from, *to;
    bool peaks;
} ThumbJob;

/* Reads what imgdiff --machine wrote (its log, stdout and stderr) into a; image is the
 * compared image's path, left out of imgdiff's complaint about it. */
static void read_answer(const char *log, const char *image, DiffAnswer *a)
{
    *a = (DiffAnswer){0};
    FILE *f = imgfile_fopen(log);
    Figures *fig = &a->figures;
    char line[1024], word[16];
    char *cannot = grade_format("imgdiff: cannot read '%s': ", image);
    while (f != NULL && fgets(line, sizeof line, f) != NULL) {
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
        } else if (strncmp(line, "imgdiff: ", 9) == 0 && a->reason[0] == '\0') {
            size_t skip = strncmp(line, cannot, strlen(cannot)) == 0 ? strlen(cannot) : 9;
            snprintf(a->reason, sizeof a->reason, "%.*s", (int)sizeof a->reason - 1, line + skip);
        } else {
            /* || stops at the first pattern that fits the line. */
            (void)(sscanf(line, "threshold %lf", &fig->threshold) == 1 ||
                   sscanf(line, "allow %lf", &fig->allow) == 1 ||
                   sscanf(line, "max %lf %lf %lf", &fig->max[0], &fig->max[1], &fig->max[2]) == 3 ||
                   sscanf(line, "mean %lf", &fig->mean) == 1 ||
                   sscanf(line, "rmse %lf", &fig->rmse) == 1 ||
                   sscanf(line, "psnr %lf", &fig->psnr) == 1 ||
                   sscanf(line, "differing %ld %ld", &fig->differing, &fig->pixels) == 2 ||
                   sscanf(line, "heat_scale %lf", &fig->heat_scale) == 1);
        }
    }
    if (f != NULL)
        fclose(f);
}

/* Sets the verdict PASS or FAIL from imgdiff's figures, with the reason in words. */
static void judge_figures(SceneResult *res, const DiffAnswer *a)
{
    const Figures *f = &a->figures;
    Verdict v = a->pass ? VERDICT_PASS : VERDICT_FAIL;
    res->compared = true;
    res->figures = *f;
    res->identical = f->max[0] == 0 && f->max[1] == 0 && f->max[2] == 0;
    if (res->identical)
        grade_verdict(res, v, "identical to the reference");
    else if (f->differing == 0)
        grade_verdict(res, v, "no pixel differs by more than %.3g/255", f->threshold * 255);
    else
        grade_verdict(res, v,
                      "%.3g%% of the pixels differ by more than %.3g/255, %s the %.3g%% allowed",
                      100.0 * f->differing / f->pixels, f->threshold * 255,
                      a->pass ? "within" : "more than", f->allow * 100);
}

/* Reads job->from, shrinks it by a whole factor to fit THUMB_SIDE and writes it as a PNG;
 * runs in a child (run_function), so returns an exit status, reasons on stderr. */
static int thumb_job(void *arg)
{
    const ThumbJob *job = arg;
    Image src, dst;
    Error err;
    ImgFileKind kind;
    int w, h;
    bool ok = imgfile_header(job->from, &kind, &w, &h, &err);
    if (ok && (long)w * h > THUMB_MAX_PIXELS) {
        error_set(&err, "%d x %d pixels: too large to show", w, h);
        ok = false;
    }
    if (!ok || !image_read(&src, job->from, &err)) {
        fprintf(stderr, "%s\n", err.text);
        return 1;
    }
    int side = src.width > src.height ? src.width : src.height;
    int f = (side + THUMB_SIDE - 1) / THUMB_SIDE;
    if (!image_init(&dst, (src.width + f - 1) / f, (src.height + f - 1) / f)) {
        fprintf(stderr, "not enough memory for the thumbnail\n");
        return 1;
    }
    for (int y = 0; y < dst.height; y++)
        for (int x = 0; x < dst.width; x++) {
            Color sum = color(0, 0, 0), peak = image_get(&src, x * f, y * f);
            int n = 0;
            for (int v = y * f; v < (y + 1) * f && v < src.height; v++)
                for (int u = x * f; u < (x + 1) * f && u < src.width; u++, n++) {
                    Color c = image_get(&src, u, v);
                    sum = color_add(sum, c);
                    peak = c.r + c.g + c.b > peak.r + peak.g + peak.b ? c : peak;
                }
            image_set(&dst, x, y, job->peaks ? peak : color_scale(sum, 1.0 / n));
        }
    /* A PNG's values go back as they were read; a PFM's or an EXR's are linear radiance,
     * encoded as raytra encodes its PNGs. Written without image_write's temporary: the
     * grader uses the file only when this child reports success. */
    PngEncoding encoding = kind == IMGFILE_PNG ? PNG_ENCODING_LINEAR : PNG_ENCODING_SRGB;
    int fd = open(job->to, O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_NONBLOCK, 0644);
    FILE *out = fd >= 0 ? fdopen(fd, "wb") : NULL;
    ok = out != NULL && image_write_png(&dst, out, encoding, &err);
    if ((out != NULL && fclose(out) != 0) || !ok) {
        fprintf(stderr, "cannot write '%s'\n", job->to);
        ok = false;
    }
    image_free(&dst);
    image_free(&src);
    return ok ? 0 : 1;
}

/* Writes to `to` a PNG thumbnail of the image `from`, in a child under a time limit and the
 * memory limit, since `from` may be a student's file; reasons go to log. Tells whether it
 * did. */
bool compare_thumb(const char *from, const char *to, bool peaks, const char *log,
                   long long memory_limit)
{
    ThumbJob job = {from, to, peaks};
    RunSpec spec = {.log = log, .time_limit = 120, .memory_limit = RUN_OWN_MEMORY(memory_limit)};
    RunResult r = run_function(thumb_job, &job, &spec);
    return r.end == RUN_EXITED && r.status == 0;
}

/* Compares image, submitted for render k, with the reference through imgdiff, and makes
 * the thumbnails the report shows. */
void compare_image(const Grading *g, const Submission *s, int k, const char *image)
{
    const Render *r = &g->renders[k];
    SceneResult *res = &s->results[k];
    char *log = grade_format("%s/%s.diff.txt", s->work, r->name);
    char *heat = grade_format("%s/%s.heat.png", s->work, r->name);
    char *show = grade_format("%s/%s.show.png", s->work, r->name);
    char *heat_show = grade_format("%s/%s.heat-show.png", s->work, r->name);
    char *argv[] = {g->imgdiff, "--machine",          "--threshold", (char *)g->threshold,
                    "--allow",  (char *)g->allow,     "--diff",      heat,
                    "--",       (char *)r->reference, (char *)image, NULL};
    RunSpec spec = {.log = log, .time_limit = 600, .memory_limit = RUN_OWN_MEMORY(g->memory_limit)};
    RunResult run = run_program(argv, &spec);
    bool exited = run.end == RUN_EXITED;
    DiffAnswer a;
    read_answer(log, image, &a);
    if (exited && run.status <= 1 && a.has_verdict)
        judge_figures(res, &a);
    else if (exited && a.has_sizes) {
        grade_verdict(res, VERDICT_WRONG_SIZE, "the image is %d x %d pixels, the reference %d x %d",
                      a.sizes[2], a.sizes[3], a.sizes[0], a.sizes[1]);
        res->relative_width = a.sizes[0] > 0 ? (double)a.sizes[2] / a.sizes[0] : 0;
    } else if (exited && a.reason[0] != '\0')
        grade_verdict(res, VERDICT_UNREADABLE, "the file cannot be read as an image: %s", a.reason);
    else if (run.end != RUN_INTERRUPTED)
        grade_verdict(res, VERDICT_UNREADABLE, "imgdiff could not compare the file (%s)",
                      run_describe(&run, spec.time_limit));
    if (res->verdict == VERDICT_UNREADABLE || run.end == RUN_INTERRUPTED || res->identical)
        return;
    if (compare_thumb(image, show, false, NULL, g->memory_limit))
        res->image_show = show;
    if (res->compared && compare_thumb(heat, heat_show, true, NULL, g->memory_limit))
        res->heat_show = heat_show;
}

/* Tells whether the file at path, found for render r, is an image handed in: a regular
 * file, not a symbolic link nor the reference itself under another name; else sets the
 * verdict, LINK or UNREADABLE. lstat only: a FIFO or a device is never opened. */
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
