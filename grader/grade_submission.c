/* grade_submission.c: the class's submissions, listed, built and run or read, judged by imgdiff. */
#include "grade.h"

#include <ctype.h>
#include <errno.h>
#include <ftw.h>
#include <libgen.h>
#include <limits.h>
#include <signal.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#include "image_read.h"
#include "imgfile.h"
#include "stop.h"

/* Returns the path of submission s's image of render k: where its program writes it, or in a
 * folder of images the file named as the reference, or with another of .png, .pfm and .exr. */
static char *image_of(const Grading *g, const Submission *s, int k)
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

/* Sets the verdict of res and its reason, made as printf makes it. */
static void DIAG_PRINTF(3, 4) set_verdict(SceneResult *res, Verdict v, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(res->message, sizeof res->message, fmt, ap);
    va_end(ap);
    res->verdict = v;
}

/* Tells whether the files at a and b hold the same bytes (both opened as a student's file). */
static bool same_bytes(const char *a, const char *b)
{
    FILE *fa = imgfile_fopen(a), *fb = imgfile_fopen(b);
    struct stat sa, sb;
    bool same = fa != NULL && fb != NULL && fstat(fileno(fa), &sa) == 0 &&
                fstat(fileno(fb), &sb) == 0 && sa.st_size == sb.st_size;
    char ca[1 << 14], cb[1 << 14];
    for (size_t n; same && (n = fread(ca, 1, sizeof ca, fa)) > 0;)
        same = fread(cb, 1, n, fb) == n && memcmp(ca, cb, n) == 0;
    same = same && !ferror(fa);
    if (fa != NULL)
        fclose(fa);
    if (fb != NULL)
        fclose(fb);
    return same;
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
        set_verdict(res, VERDICT_ERROR,
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
                              same_bytes(image, r->reference)) ||
                                 (r->shipped != NULL && same_bytes(image, r->shipped));
    /* It matches the reference: now against the program's own OTHER, exactly. */
    bool same = other != NULL && v == VERDICT_PASS;
    if (same) {
        d = run_imgdiff(g, s, k, image, image_of(g, s, r->same_as), exact);
        v = d.run.ok ? VERDICT_PASS : VERDICT_FAIL;
        res->identical = res->copy = false;
    }
    const char *why = r->why != NULL ? r->why : "", *colon = r->why != NULL ? ": " : "";
    if (res->compared && same && v == VERDICT_FAIL)
        set_verdict(res, v,
                    "%ld pixels (%.3g%%) differ from this program's own %s; the two must be "
                    "equal pixel for pixel%s%s",
                    f->differing, 100.0 * f->differing / f->pixels, other->image, colon, why);
    else if (res->compared && same)
        set_verdict(res, v, "matches the reference, and equals this program's own %s pixel for "
                    "pixel", other->image);
    else if (res->compared && r->judge == JUDGE_COVER)
        set_verdict(res, v,
                    "%.3g%% of the pixels are black here and drawn in %s, %s the %.3g%% "
                    "allowed%s%s",
                    100.0 * f->differing / f->pixels, strrchr(r->mask, '/') + 1,
                    v == VERDICT_PASS ? "within" : "more than", f->allow * 100,
                    v == VERDICT_PASS ? "" : colon, v == VERDICT_PASS ? "" : why);
    else if (res->compared && d.statistical != NULL)
        set_verdict(res, v, "%s", d.statistical);
    else if (res->identical)
        set_verdict(res, v, "identical to the reference");
    else if (res->compared && f->differing == 0)
        set_verdict(res, v, "no pixel differs by more than %.3g/255", f->threshold * 255);
    else if (res->compared)
        set_verdict(res, v,
                    "%.3g%% of the pixels differ by more than %.3g/255, %s the %.3g%% allowed",
                    100.0 * f->differing / f->pixels, f->threshold * 255,
                    v == VERDICT_PASS ? "within" : "more than", f->allow * 100);
    else if (d.size[0] > 0) {
        set_verdict(res, VERDICT_WRONG_SIZE, "the image is %d x %d pixels, the reference %d x %d",
                    d.size[2], d.size[3], d.size[0], d.size[1]);
        res->relative_width = (double)d.size[2] / d.size[0];
    } else if (d.reason != NULL)
        set_verdict(res, VERDICT_UNREADABLE, "the file cannot be read as an image: %s", d.reason);
    else if (d.run.end != RUN_INTERRUPTED)
        set_verdict(res, VERDICT_UNREADABLE, "imgdiff could not compare the file (%s)",
                    run_describe(&d.run));
}

/* Judges the file at path as the image of render k, with lstat first so that a FIFO or a
 * device is never opened: MISSING (saying `missing`), LINK, UNREADABLE, or compared. */
static void judge_file(const Grading *g, const Submission *s, int k, const char *path,
                       const char *missing)
{
    SceneResult *res = &s->results[k];
    struct stat st, ref;
    const char *name = strrchr(path, '/') + 1;
    char target[256] = "";
    if (lstat(path, &st) != 0)
        set_verdict(res, VERDICT_MISSING, "%s", missing);
    else if (S_ISLNK(st.st_mode) && readlink(path, target, sizeof target - 1) >= 0)
        set_verdict(res, VERDICT_LINK, "%s is a symbolic link to %s: not an image handed in", name,
                    target);
    else if (!S_ISREG(st.st_mode))
        set_verdict(res, VERDICT_UNREADABLE, "%s is not a regular file (%s)", name,
                    imgfile_kind_text(st.st_mode));
    else if ((stat(g->renders[k].reference, &ref) == 0 && ref.st_dev == st.st_dev &&
              ref.st_ino == st.st_ino) ||
             (g->renders[k].shipped != NULL && stat(g->renders[k].shipped, &ref) == 0 && ref.st_dev == st.st_dev &&
              ref.st_ino == st.st_ino))
        set_verdict(res, VERDICT_LINK, "%s is a hard link to the reference image", name);
    else
        compare_image(g, s, k, path);
}

/* Grades render k of a submission of images: finds the image (image_of) and judges it. */
static void grade_image(const Grading *g, Submission *s, int k)
{
    judge_file(g, s, k, image_of(g, s, k),
               grade_format("no %s.png, .pfm or .exr in the submission", g->renders[k].name));
}

/* Returns the end of a program's output (run_tail) with the work folder's path written
 * "work" (as in a compiler's -I flags, or a program naming its folder), so that what the
 * report shows does not depend on where the work folder is: a shard's, merged. */
static char *tail_of(const Grading *g, const char *output)
{
    size_t len = strlen(g->work);
    char *text = grade_alloc(strlen(output) + 1), *t = text;
    for (const char *p = output; *p != '\0';)
        if (strncmp(p, g->work, len) == 0)
            t = stpcpy(t, "work"), p += len;
        else
            *t++ = *p++;
    return run_tail(text);
}

/* Removes, in the folder it runs in, the build outputs a submission may carry from
 * another machine, which make would take as up to date: folders of builds (pruned,
 * removed whole), objects, archives, libraries, dependency files and a raytra; prints
 * each, sorted, a folder with a '/' after it, and "!failed" when one could not be removed.
 * A folder is made writable first (a build may leave it read-only); a link is never
 * followed, nor its target changed. */
static const char remove_outputs[] =
    "{ find . -mindepth 1 \\( -type d \\( -name build -o -name 'build-*' -o -name '*.dSYM' \\) "
    "-prune -o ! -type d \\( -name '*.o' -o -name '*.a' -o -name '*.d' "
    "-o -name '*.so' -o -name '*.dylib' -o -name '*.gch' -o -name raytra \\) \\) "
    "-exec sh -c 'for p; do s=; [ -d \"$p\" ] && [ ! -L \"$p\" ] && s=/; "
    "printf \"%s%s\\n\" \"${p#./}\" \"$s\"; [ -z \"$s\" ] || chmod -R u+rwX -- \"$p\"; "
    "rm -rf -- \"$p\" || exit 1; done' sh {} + "
    "|| echo '!failed'; } | LC_ALL=C sort";

/* Removes from the copy at `copy` the build outputs it carries (remove_outputs), so that
 * make builds raytra from the sources; returns what was removed, a path a line, or NULL
 * when nothing was; sets *trouble when they could not all be removed. */
static char *remove_build_outputs(const char *copy, bool *trouble)
{
    char *argv[] = {"sh", "-c", (char *)remove_outputs, NULL};
    RunResult r = run_student(argv, copy, NULL, 600, 0, &(View){{copy, NULL}, NULL, 0});
    *trouble = !r.ok || strstr(r.output, "!failed") != NULL;
    size_t n = strlen(r.output);
    while (n > 0 && r.output[n - 1] == '\n')
        n--;
    return n > 0 ? grade_format("%.*s", (int)n, r.output) : NULL;
}

/* The grading whose references' canaries replace their copies in a submission, and the
 * copy (nftw's visits take no argument of their own). */
static const Grading *planting;
static const char *planting_in;

/* nftw's visit of a file of a submission's copy: a regular file that holds a shipped
 * reference's bytes is given its canary's instead (Render.canary), by the student's cp. */
static int plant_canary(const char *path, const struct stat *st, int type, struct FTW *ftw)
{
    (void)ftw;
    for (int k = 0; type == FTW_F && S_ISREG(st->st_mode) && k < planting->render_count; k++) {
        const Render *r = &planting->renders[k];
        struct stat ref;
        if (r->canary == NULL || stat(r->shipped, &ref) != 0 || ref.st_size != st->st_size ||
            !same_bytes(path, r->shipped))
            continue;
        char *cp[] = {"cp", "-f", "--", r->canary, (char *)path, NULL}, *canary[] = {r->canary, NULL};
        run_student(cp, NULL, NULL, 60, 0, &(View){{planting_in, NULL}, canary, 0});
        break;
    }
    return 0;
}

/* Puts each reference's canary in the place of every file of the copy at `copy` that holds
 * the shipped reference's bytes: the student's user first lets the grader read all of its
 * files (its own, some of which it may have kept to itself), then the grader compares. */
static void plant_canaries(const Grading *g, const char *copy)
{
    char *let[] = {"chmod", "-R", "u+rwX,g+rX", "--", ".", NULL};
    run_student(let, copy, NULL, 60, 0, &(View){{copy, NULL}, NULL, 0});
    planting = g;
    planting_in = copy;
    nftw(copy, plant_canary, 16, FTW_PHYS);
}

/* Copies submission s into its work folder (cp -P: a link stays a link, never followed out
 * of it), removes the build outputs it carries, puts the references' canaries in place of
 * the copies of the references it holds, and runs make there under the limits; returns the
 * program it built, or NULL with the reason in s->build_message. */
static char *build(const Grading *g, Submission *s)
{
    char *copy = grade_format("%s/build", s->work), *log = grade_format("%s/build.log", s->work);
    char *program = grade_format("%s/raytra", copy);
    /* The sandbox sees the submission by its real path, read-only, and the copy. */
    char real[PATH_MAX], *from = realpath(s->path, real) != NULL ? real : s->path;
    char *source[] = {from, NULL};
    char *cp[] = {"cp", "-R", "-P", "--", grade_format("%s/.", from), copy, NULL};
    char *make[] = {"make", NULL};
    bool trouble = false;
    View own = {{copy, NULL}, NULL, g->disk_limit};
    struct stat st;
    RunResult r = run_student(cp, NULL, log, 600, 0, &(View){{copy, NULL}, source, g->disk_limit});
    if (r.ok) {
        s->removed = remove_build_outputs(copy, &trouble);
        plant_canaries(g, copy);
    }
    if (!r.ok)
        s->build_message = grade_format("the submission could not be copied to build it (cp: %s)",
                                        run_describe(&r));
    else if (trouble)
        s->build_message = "the build outputs the submission carries could not be removed";
    else if ((r = run_student(make, copy, log, g->build_time_limit, g->memory_limit, &own)).end ==
             RUN_TIMED_OUT)
        s->build_message = grade_format("make did not finish within %g s", g->build_time_limit);
    else if (r.end == RUN_OVER_DISK)
        s->build_message = grade_format("make wrote more than %s, the disk limit, or filled the "
                                        "disk: stopped, and what it wrote removed",
                                        grade_size_text(g->disk_limit));
    else if (!r.ok)
        s->build_message = grade_format("make failed (%s)", run_describe(&r));
    else if (stat(program, &st) != 0 || !S_ISREG(st.st_mode) || (st.st_mode & 0111) == 0)
        s->build_message = "make succeeded but made no executable raytra beside the Makefile";
    s->build_log_tail = tail_of(g, r.output);
    return s->build_message != NULL || r.end == RUN_INTERRUPTED ? NULL : program;
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

/* Sets the mode of those of files (a render's) that are hidden scenes' copies, which the
 * grader keeps from the students' users (part_render_hidden) but while they are rendered. */
static void show_hidden(const Grading *g, char **files, mode_t mode)
{
    char *hidden = grade_format("%s/hidden-scenes/", g->work);
    for (char **f = files; *f != NULL; f++)
        if (strncmp(*f, hidden, strlen(hidden)) == 0)
            chmod(*f, mode);
}

/* Grades render k of a submission that is a program: runs it on the scene under the
 * limits, in a scratch folder, and judges how it ended and what it wrote. */
static void run_scene(const Grading *g, Submission *s, int k)
{
    const Render *r = &g->renders[k];
    SceneResult *res = &s->results[k];
    char *log = grade_format("%s/%s.log", s->work, r->name);
    char *image = image_of(g, s, k);
    /* The program and its image are named from the run folder, so that neither what it
     * prints nor its command line depends on where the work folder is (a shard's, merged). */
    r->argv[0] = "../build/raytra";
    r->argv[2] = grade_format("../images/%s", r->image);
    char *dir = grade_format("%s/run", s->work);
    /* The sandbox: the run and images folders to write; the build and the scene to read. */
    char **files = sandbox_scene_files(r->argv[1], dir, grade_format("%s/build", s->work));
    View view = {{dir, grade_format("%s/images", s->work), NULL}, files, g->disk_limit};
    /* A hidden scene's files are the grader's alone but while they are rendered. */
    show_hidden(g, files, 0644);
    RunResult run = run_student(r->argv, dir, log, g->time_limit, g->memory_limit, &view);
    show_hidden(g, files, 0600);
    res->seconds = run.seconds;
    res->log_tail = tail_of(g, run.output);
    res->command = run_command_line(r->argv, NULL);
    char *how = run_describe(&run);
    struct stat st;
    bool wrote = lstat(image, &st) == 0, exited = run.end == RUN_EXITED;
    bool failed = run.end == RUN_KILLED || (exited && run.status != 0);
    /* The kernel's out-of-memory killer sends SIGKILL; the grader's own kills are timeouts. */
    if (failed &&
        (says_out_of_memory(res->log_tail) || (run.end == RUN_KILLED && run.status == SIGKILL)))
        set_verdict(res, VERDICT_OUT_OF_MEMORY, "ran out of memory (%s; memory limit %s)", how,
                    grade_size_text(g->memory_limit));
    else if (run.end == RUN_TIMED_OUT)
        set_verdict(res, VERDICT_TIMEOUT, "did not finish within %g s", g->time_limit);
    else if (run.end == RUN_OVER_DISK)
        set_verdict(res, VERDICT_ERROR, "wrote more than %s, the disk limit, or filled the disk: "
                    "stopped, and what it wrote removed", grade_size_text(g->disk_limit));
    else if (run.end == RUN_KILLED)
        set_verdict(res, VERDICT_CRASHED, "%s", how);
    else if (run.end == RUN_NOT_RUN)
        set_verdict(res, VERDICT_ERROR, "the grader could not start the program (%s)", how);
    else if (!wrote && failed)
        set_verdict(res, VERDICT_ERROR, "ended with %s and wrote no image", how);
    else if (exited)
        judge_file(g, s, k, image, grade_format("ended normally but wrote no %s", r->image));
    /* An image written before a failure exit is graded; the failure is told. */
    if (wrote && failed && exited && res->verdict != VERDICT_OUT_OF_MEMORY) {
        size_t len = strlen(res->message);
        snprintf(res->message + len, sizeof res->message - len, "; the program ended with %s", how);
    }
}

/* Makes the work folders of submission s fresh (a folder that a classmate's program made in
 * the place of one is moved aside, told on f): its own, and for a program images/ and run/;
 * returns NULL, or why they could not be made. */
static const char *make_work(const Submission *s, FILE *f)
{
    const char *trouble = path_fresh_folder(s->work, f);
    /* A program is built and run, in folders of its own; a folder of images is read. */
    if (trouble == NULL && s->program && s->link == NULL)
        trouble = path_fresh_folder(grade_format("%s/images", s->work), f);
    if (trouble == NULL && s->program && s->link == NULL)
        trouble = path_fresh_folder(grade_format("%s/run", s->work), f);
    /* The build's copy too, so that a student's user (--run-as) may write in all three. */
    if (trouble == NULL && s->program && s->link == NULL)
        trouble = path_fresh_folder(grade_format("%s/build", s->work), f);
    /* Its users must reach the three: the folder is crossed, not read (whatever the umask). */
    if (trouble == NULL && contain_active() && chmod(s->work, 0711) != 0)
        trouble = grade_format("cannot open %s to the student's user: %s", s->work,
                               strerror(errno));
    static const char *const shared[] = {"images", "run", "build"};
    for (size_t k = 0; k < 3 && trouble == NULL && s->program && s->link == NULL; k++)
        if (!contain_share(grade_format("%s/%s", s->work, shared[k])))
            trouble = grade_format("cannot open %s/%s to the student's user: %s", s->work,
                                   shared[k], strerror(errno));
    return trouble;
}

/* Grades every render of submission s, whose work folders were made unless `trouble` says
 * why not; counts the verdicts and tells them on f ("5 scenes: 4 pass, 1 timeout"); false
 * when grading must stop (interrupted). */
static bool grade_one(const Grading *g, Submission *s, const char *trouble, FILE *f)
{
    s->results = grade_alloc((size_t)g->render_count * sizeof *s->results);
    char *program = trouble == NULL && s->program && s->link == NULL ? build(g, s) : NULL;
    for (int k = 0; k < g->render_count && !stop_requested(); k++) {
        /* A folder that is a link (to a classmate's) is not a submission of its own. */
        if (trouble != NULL)
            set_verdict(&s->results[k], VERDICT_ERROR,
                        "the grader could not make its work "
                        "folder: %s",
                        trouble);
        else if (s->link != NULL)
            set_verdict(&s->results[k], VERDICT_LINK,
                        "the submission's folder is a symbolic link to %s", s->link);
        else if (!s->program)
            grade_image(g, s, k);
        else if (program != NULL)
            run_scene(g, s, k);
        else
            set_verdict(&s->results[k], VERDICT_BUILD_FAILED, "%s", s->build_message);
    }
    if (stop_requested()) {
        fputc('\n', f);
        return false;
    }
    int count[VERDICT_COUNT] = {0};
    for (int k = 0; k < g->render_count; k++) {
        count[s->results[k].verdict]++;
        s->tally[verdict_info[s->results[k].verdict].tally]++;
    }
    if (s->build_message != NULL) {
        fprintf(f, "BUILD FAILED: %s\n", s->build_message);
        return true;
    }
    fprintf(f, "%d scene%s:", g->render_count, g->render_count == 1 ? "" : "s");
    const char *sep = " ";
    for (int v = 0; v < VERDICT_COUNT; v++) {
        if (count[v] == 0)
            continue;
        fprintf(f, "%s%d ", sep, count[v]);
        for (const char *p = verdict_info[v].name; *p != '\0'; p++)
            fputc(tolower((unsigned char)*p), f);
        sep = ", ";
    }
    fputc('\n', f);
    return true;
}

/* Grades submission s, telling the progress on f: its name and kind, then how its scenes
 * fared ("5 scenes: 4 pass, 1 timeout"); false when grading must stop (interrupted). */
bool submission_grade(const Grading *g, Submission *s, FILE *f)
{
    const char *trouble = make_work(s, f);
    /* Control characters made '?': a folder's name cannot play tricks on the terminal. */
    fprintf(f, "grading ");
    for (const char *p = s->name; *p != '\0'; p++)
        fputc((unsigned char)*p < 0x20 || *p == 0x7F ? '?' : *p, f);
    fprintf(f, " (%s): %s", s->program ? "program" : "images", s->program ? "building... " : "");
    bool graded = grade_one(g, s, trouble, f);
    /* Graded: with --run-as, closed to the students' users, who may be the next one's too. */
    if (contain_active())
        chmod(s->work, 0700);
    return graded;
}

/* Lists the submissions, each with a work folder named safely for scripts (03-alice): the
 * folders in g->submissions by name, but hidden ones and the output folder, or with --self
 * the one folder; false (reported) when there are none. */
bool submission_list(Grading *g)
{
    static const char *const makefiles[] = {"GNUmakefile", "makefile", "Makefile"};
    int count = 1;
    char real[PATH_MAX];
    /* --self's one folder is named as it is, "." or "../alice/" too: by its real path. */
    char *self[] = {basename(realpath(g->submissions, real) != NULL
                                 ? grade_format("%s", real)
                                 : grade_format("%s", g->submissions))};
    char **names = g->self ? self : path_list_folders(g->submissions, &count);
    if (names == NULL)
        return grade_fail("cannot read the folder %s: %s", g->submissions, strerror(errno));
    g->subs = grade_alloc((size_t)count * sizeof *g->subs);
    int digits = count < 100 ? 2 : count < 1000 ? 3 : 6;
    for (int k = 0; k < count; k++) {
        char *path = g->self ? grade_format("%s", g->submissions)
                             : grade_format("%s/%s", g->submissions, names[k]);
        /* The output folder is the one whose work folder is g->work. */
        if (!g->self && realpath(path, real) != NULL &&
            strcmp(grade_format("%s/work", real), g->work) == 0)
            continue;
        /* So is another run's (a lock file and a work folder that grade marked). */
        if (!g->self && path_kind(grade_format("%s/.grade-lock", path)) == S_IFREG &&
            path_kind(grade_format("%s/work/.made-by-grade", path)) == S_IFREG) {
            fprintf(g->progress, "grade: note: %s is an output folder of grade: not graded\n",
                    path);
            continue;
        }
        Submission *s = &g->subs[g->sub_count++];
        char *work = g->self ? grade_format("%s/1-self", g->work)
                             : grade_format("%s/%0*d-%.40s", g->work, digits, g->sub_count,
                                            names[k]);
        for (char *p = strrchr(work, '/') + 1; *p != '\0'; p++)
            if (!isalnum((unsigned char)*p) && *p != '.' && *p != '_' && *p != '-')
                *p = '_';
        *s = (Submission){.name = grade_format("%s", names[k]), .path = path, .work = work};
        /* A program holds a Makefile, as make looks for one. */
        for (size_t m = 0; m < sizeof makefiles / sizeof makefiles[0]; m++)
            s->program |= path_kind(grade_format("%s/%s", path, makefiles[m])) == S_IFREG;
        /* A folder of the class that is a link (to a classmate's) is not graded as one. */
        ssize_t n = g->self ? -1 : readlink(path, real, sizeof real - 1);
        if (n >= 0)
            s->link = grade_format("%.*s", (int)n, real);
    }
    return g->sub_count > 0 ||
           grade_fail("no submissions in %s: it should hold a folder a student", g->submissions);
}
