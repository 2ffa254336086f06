/* grade_submission.c: grading a submission: building and running it, or finding its images. */
#include "grade_submission.h"

#include <errno.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include "grade_run.h"
#include "grade_thumb.h"
#include "imgfile.h"
#include "stop.h"

/* The log tail keeps at most this much of the end of a program's output. */
#define TAIL_BYTES 2048
#define TAIL_LINES 20

/* What imgdiff --machine said about an image against its reference. */
typedef struct {
    Figures figures;
    bool has_verdict, pass;
    bool has_sizes;
    int sizes[4];     /* the reference's width and height, then the image's */
    char reason[400]; /* imgdiff's complaint, when it made one */
} DiffAnswer;

/* Sets the verdict of res and its reason, made as printf makes it. */
static void set_verdict(SceneResult *res, Verdict v, const char *fmt, ...) DIAG_PRINTF(3, 4);
static void set_verdict(SceneResult *res, Verdict v, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(res->message, sizeof res->message, fmt, ap);
    va_end(ap);
    res->verdict = v;
}

/* Tells whether path is a regular file. */
static bool regular_file(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

/* Writes into text how a run ended: "exit status 2", "killed by signal 11 (Segmentation
 * fault)", "still running after 60 s". */
static void describe_end(const RunResult *r, double limit, char *text, size_t size)
{
    switch (r->end) {
    case RUN_EXITED: snprintf(text, size, "exit status %d", r->status); break;
    case RUN_KILLED:
        snprintf(text, size, "killed by signal %d (%s)", r->status, strsignal(r->status));
        break;
    case RUN_TIMED_OUT: snprintf(text, size, "still running after %g s", limit); break;
    case RUN_NOT_RUN: snprintf(text, size, "not started: %s", strerror(r->status)); break;
    case RUN_INTERRUPTED: snprintf(text, size, "interrupted"); break;
    }
}

/* Tells whether a program's last output says that it ran out of memory, in the words of
 * C's and C++'s libraries and of the common messages. */
static bool says_out_of_memory(const char *output)
{
    static const char *const phrases[] = {
        "out of memory",     "cannot allocate memory", "bad_alloc",         "memory exhausted",
        "not enough memory", "failed to allocate",     "allocation failed",
    };
    for (const char *p = output; p != NULL && *p != '\0'; p++)
        for (size_t k = 0; k < sizeof phrases / sizeof phrases[0]; k++)
            if (strncasecmp(p, phrases[k], strlen(phrases[k])) == 0)
                return true;
    return false;
}

/* Returns the number of bytes at the start of s[0..n) that continue a UTF-8 character
 * begun before it, so that a tail cut in the middle of one starts cleanly. */
static size_t continuation_bytes(const char *s, size_t n)
{
    size_t i = 0;
    while (i < n && ((unsigned char)s[i] & 0xC0) == 0x80)
        i++;
    return i;
}

/* Copies the output raw[0..n) into out as a terminal would show it: a carriage return
 * starts its line again (a progress bar leaves its last state), escape sequences go,
 * other control characters become '?'; returns the length written. */
static size_t clean_output(const char *raw, size_t n, char *out)
{
    size_t len = 0, line_start = 0;
    for (size_t i = 0; i < n; i++) {
        unsigned char c = (unsigned char)raw[i];
        if (c == '\r' && (i + 1 == n || raw[i + 1] != '\n')) {
            len = line_start;
        } else if (c == '\n') {
            out[len++] = '\n';
            line_start = len;
        } else if (c == 0x1B && i + 1 < n && raw[i + 1] == '[') {
            /* ESC [ parameters, then a final byte from @ to ~: colours, erasing. */
            i += 2;
            while (i < n && !((unsigned char)raw[i] >= '@' && (unsigned char)raw[i] <= '~'))
                i++;
        } else if (c != '\r') {
            out[len++] = (c < 0x20 && c != '\t') || c == 0x7F ? '?' : (char)c;
        }
    }
    while (len > 0 && (out[len - 1] == '\n' || out[len - 1] == ' ' || out[len - 1] == '\t'))
        len--;
    out[len] = '\0';
    return len;
}

/* Returns the last lines of the file at path (a program's output), cleaned for showing,
 * with "[...]" first when some were left out; NULL when it is empty or unreadable. */
static char *log_tail(const char *path)
{
    FILE *f = imgfile_fopen(path);
    if (f == NULL)
        return NULL;
    long size = fseek(f, 0, SEEK_END) == 0 ? ftell(f) : -1;
    long from = size > TAIL_BYTES ? size - TAIL_BYTES : 0;
    char raw[TAIL_BYTES];
    size_t n = size >= 0 && fseek(f, from, SEEK_SET) == 0 ? fread(raw, 1, sizeof raw, f) : 0;
    fclose(f);
    size_t skip = from > 0 ? continuation_bytes(raw, n) : 0;
    char *text = grade_alloc(n + 1);
    size_t len = clean_output(raw + skip, n - skip, text);
    /* Keep the last TAIL_LINES lines, and only whole ones when the start was cut. */
    size_t start = 0;
    int lines = 0;
    for (size_t i = len; i > 0; i--)
        if (text[i - 1] == '\n' && ++lines == TAIL_LINES) {
            start = i;
            break;
        }
    if (from > 0 && start == 0 && len > 0) {
        char *newline = strchr(text, '\n');
        start = newline != NULL ? (size_t)(newline - text) + 1 : 0;
    }
    char *tail = len == 0
                     ? NULL
                     : grade_format("%s%s", from > 0 || start > 0 ? "[...]\n" : "", text + start);
    free(text);
    return tail;
}

/* Reads a line of imgdiff's figures into fig, if it is one; psnr may be "inf". */
static void read_figure(const char *line, Figures *fig)
{
    /* || stops at the first pattern that fits the line. */
    (void)(sscanf(line, "threshold %lf", &fig->threshold) == 1 ||
           sscanf(line, "allow %lf", &fig->allow) == 1 ||
           sscanf(line, "size %d %d", &fig->width, &fig->height) == 2 ||
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
    if (f->max[0] == 0 && f->max[1] == 0 && f->max[2] == 0)
        set_verdict(res, v, "identical to the reference");
    else if (f->differing == 0)
        set_verdict(res, v, "no pixel differs by more than %.3g/255", f->threshold * 255);
    else
        set_verdict(res, v,
                    "%.3g%% of the pixels differ by more than %.3g/255, %s the %.3g%% allowed",
                    percent, f->threshold * 255, a->pass ? "within" : "more than", f->allow * 100);
}

/* Compares image, submitted for render k, with the reference through imgdiff, and makes
 * the thumbnails the report shows. */
static void compare_image(const Grading *g, const Submission *s, int k, const char *image)
{
    const Render *r = &g->renders[k];
    SceneResult *res = &s->results[k];
    char *log = grade_format("%s/%s.diff.txt", s->work, r->name);
    char *heat = grade_format("%s/%s.heat.png", s->work, r->name);
    const char *reference = r->reference, *compared = image;
    char *argv[] = {g->imgdiff, "--machine",       "--threshold",    (char *)g->threshold,
                    "--allow",  (char *)g->allow,  "--diff",         heat,
                    "--",       (char *)reference, (char *)compared, NULL};
    RunSpec spec = {.log = log, .time_limit = 600, .memory_limit = RUN_OWN_MEMORY(g->memory_limit)};
    RunResult run = run_program(argv, &spec);
    DiffAnswer a;
    read_answer(log, compared, &a);
    char how[200];
    describe_end(&run, spec.time_limit, how, sizeof how);
    if (run.end == RUN_EXITED && run.status <= 1 && a.has_verdict)
        judge_figures(res, &a);
    else if (run.end == RUN_EXITED && a.has_sizes) {
        set_verdict(res, VERDICT_WRONG_SIZE, "the image is %d x %d pixels, the reference %d x %d",
                    a.sizes[2], a.sizes[3], a.sizes[0], a.sizes[1]);
        res->relative_width = a.sizes[0] > 0 ? (double)a.sizes[2] / a.sizes[0] : 0;
    } else if (run.end == RUN_EXITED && a.reason[0] != '\0')
        set_verdict(res, VERDICT_UNREADABLE, "the file cannot be read as an image: %s", a.reason);
    else if (run.end != RUN_INTERRUPTED)
        set_verdict(res, VERDICT_UNREADABLE, "imgdiff could not compare the file (%s)", how);
    res->identical =
        res->compared && a.figures.max[0] == 0 && a.figures.max[1] == 0 && a.figures.max[2] == 0;
    if (res->verdict == VERDICT_UNREADABLE || run.end == RUN_INTERRUPTED || res->identical)
        goto done;
    char *show = grade_format("%s/%s.show.png", s->work, r->name);
    char *heat_show = grade_format("%s/%s.heat-show.png", s->work, r->name);
    if (thumb_make(compared, show, THUMB_SIDE, THUMB_MEAN, NULL, g->memory_limit))
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
static bool handed_in(const Render *r, SceneResult *res, const char *path)
{
    struct stat st, ref;
    const char *name = strrchr(path, '/') + 1;
    char target[256] = "";
    if (lstat(path, &st) != 0) {
        set_verdict(res, VERDICT_UNREADABLE, "%s cannot be read: %s", name, strerror(errno));
    } else if (S_ISLNK(st.st_mode)) {
        ssize_t n = readlink(path, target, sizeof target - 1);
        target[n > 0 ? n : 0] = '\0';
        set_verdict(res, VERDICT_LINK, "%s is a symbolic link to %s: not an image handed in", name,
                    target);
    } else if (!S_ISREG(st.st_mode)) {
        set_verdict(res, VERDICT_UNREADABLE, "%s is not a regular file (%s)", name,
                    S_ISFIFO(st.st_mode)  ? "a FIFO"
                    : S_ISDIR(st.st_mode) ? "a folder"
                                          : "a special file");
    } else if (stat(r->reference, &ref) == 0 && ref.st_dev == st.st_dev &&
               ref.st_ino == st.st_ino) {
        set_verdict(res, VERDICT_LINK, "%s is a hard link to the reference image", name);
    } else {
        return true;
    }
    return false;
}

/* Grades render k of a submission of images: finds the image, by the reference's name or
 * with another of .png, .pfm and .exr, and compares it. */
static void grade_image(const Grading *g, Submission *s, int k)
{
    const Render *r = &g->renders[k];
    SceneResult *res = &s->results[k];
    static const char *const endings[] = {"", ".png", ".pfm", ".exr"};
    char *found = NULL;
    struct stat st;
    for (size_t e = 0; e < sizeof endings / sizeof endings[0] && found == NULL; e++) {
        found = e == 0 ? grade_format("%s/%s", s->path, r->image)
                       : grade_format("%s/%s%s", s->path, r->name, endings[e]);
        if (lstat(found, &st) != 0) {
            free(found);
            found = NULL;
        }
    }
    if (found == NULL)
        set_verdict(res, VERDICT_MISSING, "no %s.png, .pfm or .exr in the submission", r->name);
    else if (handed_in(r, res, found))
        compare_image(g, s, k, found);
    free(found);
}

/* Copies submission s into its work folder and runs make there under the limits; returns
 * the program it built, or NULL with the reason in s->build_message. */
static char *build(const Grading *g, Submission *s)
{
    char *copy = grade_format("%s/build", s->work);
    char *log = grade_format("%s/build.log", s->work);
    char *from = grade_format("%s/.", s->path);
    char *program = grade_format("%s/raytra", copy);
    char how[200];
    /* -P: a link in the submission stays a link, and is never followed out of it. */
    char *cp[] = {"cp", "-R", "-P", "--", from, copy, NULL};
    RunSpec spec = {.log = log, .time_limit = 600};
    RunResult r = run_program(cp, &spec);
    describe_end(&r, spec.time_limit, how, sizeof how);
    char *message = s->build_message;
    size_t size = sizeof s->build_message;
    if (r.end != RUN_EXITED || r.status != 0) {
        snprintf(message, size, "the submission could not be copied to build it (cp: %s)", how);
    } else {
        char *make[] = {"make", NULL};
        spec = (RunSpec){.dir = copy,
                         .log = log,
                         .time_limit = g->build_time_limit,
                         .memory_limit = g->memory_limit};
        r = run_program(make, &spec);
        describe_end(&r, spec.time_limit, how, sizeof how);
        if (r.end == RUN_TIMED_OUT)
            snprintf(message, size, "make did not finish within %g s", g->build_time_limit);
        else if (r.end != RUN_EXITED || r.status != 0)
            snprintf(message, size, "make failed (%s)", how);
        else if (!regular_file(program) || access(program, X_OK) != 0)
            snprintf(message, size,
                     "make succeeded but made no executable raytra beside the "
                     "Makefile");
    }
    s->build_log_tail = log_tail(log);
    if (message[0] != '\0' || r.end == RUN_INTERRUPTED) {
        free(program);
        program = NULL;
    }
    free(from);
    free(log);
    free(copy);
    return program;
}

/* Grades render k of a submission that is a program: runs it on the scene under the
 * limits, in a scratch folder, and judges how it ended and what it wrote. */
static void run_scene(const Grading *g, Submission *s, int k, const char *program)
{
    const Render *r = &g->renders[k];
    SceneResult *res = &s->results[k];
    char *image = grade_format("%s/images/%s", s->work, r->image);
    char *log = grade_format("%s/%s.log", s->work, r->name);
    char *scratch = grade_format("%s/run", s->work);
    int n = 0;
    while (r->args[n] != NULL)
        n++;
    char **argv = grade_alloc(((size_t)n + 4) * sizeof *argv);
    argv[0] = (char *)program;
    argv[1] = r->scene_path;
    argv[2] = image;
    memcpy(argv + 3, r->args, ((size_t)n + 1) * sizeof *argv);
    RunSpec spec = {
        .dir = scratch, .log = log, .time_limit = g->time_limit, .memory_limit = g->memory_limit};
    RunResult run = run_program(argv, &spec);
    res->seconds = run.seconds;
    res->log_tail = log_tail(log);
    char how[200];
    describe_end(&run, g->time_limit, how, sizeof how);
    struct stat st;
    bool wrote = lstat(image, &st) == 0;
    bool failed = run.end == RUN_KILLED || (run.end == RUN_EXITED && run.status != 0);
    char limit[32];
    grade_size_text(g->memory_limit, limit, sizeof limit);
    /* The kernel's out-of-memory killer sends SIGKILL; the grader's own kills are timeouts. */
    if (failed &&
        (says_out_of_memory(res->log_tail) || (run.end == RUN_KILLED && run.status == SIGKILL)))
        set_verdict(res, VERDICT_OUT_OF_MEMORY, "ran out of memory (%s; memory limit %s)", how,
                    limit);
    else if (run.end == RUN_TIMED_OUT)
        set_verdict(res, VERDICT_TIMEOUT, "did not finish within %g s", g->time_limit);
    else if (run.end == RUN_KILLED)
        set_verdict(res, VERDICT_CRASHED, "%s", how);
    else if (run.end == RUN_NOT_RUN)
        set_verdict(res, VERDICT_ERROR, "the grader could not start the program (%s)", how);
    else if (run.end == RUN_EXITED && !wrote && run.status != 0)
        set_verdict(res, VERDICT_ERROR, "ended with %s and wrote no image", how);
    else if (run.end == RUN_EXITED && !wrote)
        set_verdict(res, VERDICT_MISSING, "ended normally but wrote no %s", r->image);
    else if (run.end == RUN_EXITED && handed_in(r, res, image))
        compare_image(g, s, k, image);
    /* An image written before a failure exit is graded; the failure is told. */
    if (run.end == RUN_EXITED && wrote && run.status != 0 &&
        res->verdict != VERDICT_OUT_OF_MEMORY) {
        size_t len = strlen(res->message);
        snprintf(res->message + len, sizeof res->message - len, "; the program ended with %s", how);
    }
    free(argv);
    free(scratch);
    free(log);
    free(image);
}

/* Makes folder path; false (reported) when it cannot. */
static bool make_folder(const char *path)
{
    if (mkdir(path, 0777) == 0)
        return true;
    fprintf(stderr, "grade: cannot make the folder %s: %s\n", path, strerror(errno));
    return false;
}

/* Grades every render of submission s into s->results and counts the verdicts; false
 * when grading must stop (interrupted, or the grader's own trouble, reported). */
bool submission_grade(const Grading *g, Submission *s)
{
    s->results = grade_alloc((size_t)g->render_count * sizeof *s->results);
    for (int k = 0; k < g->render_count; k++)
        s->results[k].seconds = -1;
    if (!make_folder(s->work))
        return false;
    char *program = NULL;
    if (s->program && s->link == NULL) {
        char *images = grade_format("%s/images", s->work);
        char *scratch = grade_format("%s/run", s->work);
        bool ok = make_folder(images) && make_folder(scratch);
        free(images);
        free(scratch);
        if (!ok)
            return false;
        program = build(g, s);
    }
    for (int k = 0; k < g->render_count && !stop_requested(); k++) {
        /* A folder that is a link (to a classmate's) is not a submission of its own. */
        if (s->link != NULL)
            set_verdict(&s->results[k], VERDICT_LINK,
                        "the submission's folder is a symbolic link to %s", s->link);
        else if (!s->program)
            grade_image(g, s, k);
        else if (program != NULL)
            run_scene(g, s, k, program);
        else
            set_verdict(&s->results[k], VERDICT_BUILD_FAILED, "%s", s->build_message);
    }
    free(program);
    for (int k = 0; k < g->render_count; k++) {
        s->verdicts[s->results[k].verdict]++;
        s->tally[verdict_tally(s->results[k].verdict)]++;
    }
    return !stop_requested();
}
