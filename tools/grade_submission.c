/* grade_submission.c: the class's submissions: listed, then built and run or their images found. */
#include "grade.h"

#include <ctype.h>
#include <errno.h>
#include <libgen.h>
#include <limits.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include "stop.h"

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

/* Grades render k of a submission of images: finds the image, by the reference's name or
 * with another of .png, .pfm and .exr, and compares it. */
static void grade_image(const Grading *g, Submission *s, int k)
{
    const Render *r = &g->renders[k];
    static const char *const endings[] = {".png", ".pfm", ".exr"};
    char *found = grade_format("%s/%s", s->path, r->image);
    struct stat st;
    for (size_t e = 0; e < sizeof endings / sizeof *endings && lstat(found, &st) != 0; e++)
        found = grade_format("%s/%s%s", s->path, r->name, endings[e]);
    if (lstat(found, &st) != 0)
        grade_verdict(&s->results[k], VERDICT_MISSING, "no %s.png, .pfm or .exr in the submission",
                      r->name);
    else if (compare_handed_in(r, &s->results[k], found))
        compare_image(g, s, k, found);
}

/* Copies submission s into its work folder (cp -P: a link stays a link, never followed out
 * of it) and runs make there under the limits; returns the program it built, or NULL with
 * the reason in s->build_message. */
static char *build(const Grading *g, Submission *s)
{
    char *copy = grade_format("%s/build", s->work), *log = grade_format("%s/build.log", s->work);
    char *program = grade_format("%s/raytra", copy), *message = s->build_message;
    char *cp[] = {"cp", "-R", "-P", "--", grade_format("%s/.", s->path), copy, NULL};
    char *make[] = {"make", NULL};
    size_t size = sizeof s->build_message;
    RunSpec spec = {.log = log, .time_limit = 600};
    RunResult r = run_program(cp, &spec);
    if (r.end != RUN_EXITED || r.status != 0) {
        snprintf(message, size, "the submission could not be copied to build it (cp: %s)",
                 run_describe(&r, spec.time_limit));
    } else {
        spec = (RunSpec){copy, log, g->build_time_limit, g->memory_limit};
        r = run_program(make, &spec);
        if (r.end == RUN_TIMED_OUT)
            snprintf(message, size, "make did not finish within %g s", g->build_time_limit);
        else if (r.end != RUN_EXITED || r.status != 0)
            snprintf(message, size, "make failed (%s)", run_describe(&r, spec.time_limit));
        else if (grade_kind(program) != S_IFREG || access(program, X_OK) != 0)
            snprintf(message, size, "make succeeded but made no executable raytra beside the "
                                    "Makefile");
    }
    s->build_log_tail = run_log_tail(log);
    return message[0] != '\0' || r.end == RUN_INTERRUPTED ? NULL : program;
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
    RunSpec spec = {scratch, log, g->time_limit, g->memory_limit};
    RunResult run = run_program(argv, &spec);
    res->seconds = run.seconds;
    res->log_tail = run_log_tail(log);
    char *how = run_describe(&run, g->time_limit);
    struct stat st;
    bool wrote = lstat(image, &st) == 0, exited = run.end == RUN_EXITED;
    bool failed = run.end == RUN_KILLED || (exited && run.status != 0);
    /* The kernel's out-of-memory killer sends SIGKILL; the grader's own kills are timeouts. */
    if (failed &&
        (says_out_of_memory(res->log_tail) || (run.end == RUN_KILLED && run.status == SIGKILL)))
        grade_verdict(res, VERDICT_OUT_OF_MEMORY, "ran out of memory (%s; memory limit %s)", how,
                      grade_size_text(g->memory_limit));
    else if (run.end == RUN_TIMED_OUT)
        grade_verdict(res, VERDICT_TIMEOUT, "did not finish within %g s", g->time_limit);
    else if (run.end == RUN_KILLED)
        grade_verdict(res, VERDICT_CRASHED, "%s", how);
    else if (run.end == RUN_NOT_RUN)
        grade_verdict(res, VERDICT_ERROR, "the grader could not start the program (%s)", how);
    else if (exited && !wrote && failed)
        grade_verdict(res, VERDICT_ERROR, "ended with %s and wrote no image", how);
    else if (exited && !wrote)
        grade_verdict(res, VERDICT_MISSING, "ended normally but wrote no %s", r->image);
    else if (exited && compare_handed_in(r, res, image))
        compare_image(g, s, k, image);
    /* An image written before a failure exit is graded; the failure is told. */
    if (exited && wrote && failed && res->verdict != VERDICT_OUT_OF_MEMORY) {
        size_t len = strlen(res->message);
        snprintf(res->message + len, sizeof res->message - len, "; the program ended with %s", how);
    }
}

/* Grades every render of submission s into s->results and counts the verdicts; false
 * when grading must stop (interrupted, or the grader's own trouble, reported). */
static bool grade_one(const Grading *g, Submission *s)
{
    s->results = grade_alloc((size_t)g->render_count * sizeof *s->results);
    for (int k = 0; k < g->render_count; k++)
        s->results[k].seconds = -1;
    /* A program is built and run, in folders of its own; a folder of images is read. */
    bool runs = s->program && s->link == NULL;
    bool ok = grade_make_folder(s->work, true) &&
              (!runs || (grade_make_folder(grade_format("%s/images", s->work), true) &&
                         grade_make_folder(grade_format("%s/run", s->work), true)));
    char *program = ok && runs ? build(g, s) : NULL;
    for (int k = 0; ok && k < g->render_count && !stop_requested(); k++) {
        /* A folder that is a link (to a classmate's) is not a submission of its own. */
        if (s->link != NULL)
            grade_verdict(&s->results[k], VERDICT_LINK,
                          "the submission's folder is a symbolic link to %s", s->link);
        else if (!s->program)
            grade_image(g, s, k);
        else if (program != NULL)
            run_scene(g, s, k, program);
        else
            grade_verdict(&s->results[k], VERDICT_BUILD_FAILED, "%s", s->build_message);
    }
    for (int k = 0; k < g->render_count; k++)
        s->tally[verdict_info[s->results[k].verdict].tally]++;
    return ok && !stop_requested();
}

/* Prints how the scenes of s went: "5 scenes: 4 pass, 1 timeout". */
static void print_tally(const Grading *g, const Submission *s)
{
    if (s->build_message[0] != '\0') {
        fprintf(stderr, "BUILD FAILED: %s\n", s->build_message);
        return;
    }
    fprintf(stderr, "%d scene%s:", g->render_count, g->render_count == 1 ? "" : "s");
    const char *sep = " ";
    for (int v = 0; v < VERDICT_COUNT; v++) {
        int count = 0;
        for (int k = 0; k < g->render_count; k++)
            count += s->results[k].verdict == (Verdict)v;
        if (count == 0)
            continue;
        fprintf(stderr, "%s%d ", sep, count);
        for (const char *p = verdict_info[v].name; *p != '\0'; p++)
            fputc(tolower((unsigned char)*p), stderr);
        sep = ", ";
    }
    fputc('\n', stderr);
}

/* Grades every submission, telling the progress unless g->quiet; false when interrupted
 * or when the grader itself failed (reported). */
bool submission_grade_all(Grading *g)
{
    for (int k = 0; k < g->sub_count; k++) {
        Submission *s = &g->subs[k];
        if (!g->quiet) {
            /* Control characters made '?': a folder's name cannot play tricks on the terminal. */
            fprintf(stderr, "grading ");
            for (const char *p = s->name; *p != '\0'; p++)
                fputc((unsigned char)*p < 0x20 || *p == 0x7F ? '?' : *p, stderr);
            fprintf(stderr, " (%s): %s", s->program ? "program" : "images",
                    s->program ? "building... " : "");
        }
        bool ok = grade_one(g, s);
        if (!g->quiet && ok)
            print_tally(g, s);
        else if (!g->quiet)
            fputc('\n', stderr);
        if (!ok)
            return false;
    }
    return true;
}

/* Adds the submission in the folder path, named name, with its work folder, to g; takes
 * path and work. It is a program when it holds a Makefile, as make looks for one. */
static void add_submission(Grading *g, const char *name, char *path, char *work)
{
    static const char *const makefiles[] = {"GNUmakefile", "makefile", "Makefile"};
    Submission *s = &g->subs[g->sub_count++];
    *s = (Submission){.name = grade_format("%s", name), .path = path, .work = work};
    for (size_t k = 0; k < sizeof makefiles / sizeof makefiles[0]; k++)
        s->program |= grade_kind(grade_format("%s/%s", path, makefiles[k])) == S_IFREG;
    /* A folder of the class that is a link (to a classmate's) is not graded as one. */
    char target[PATH_MAX];
    ssize_t n = g->self ? -1 : readlink(path, target, sizeof target - 1);
    if (n >= 0)
        s->link = grade_format("%.*s", (int)n, target);
}

/* Lists the submissions: the folders in g->submissions but hidden ones and the output
 * folder, in the order of their names, each with a work folder named safely for scripts
 * (03-alice); or with --self the one folder. False (reported) when there are none. */
bool submission_list(Grading *g)
{
    if (g->self) {
        char *path = grade_format("%s", g->submissions);
        g->subs = grade_alloc(sizeof *g->subs);
        add_submission(g, basename(grade_format("%s", path)), path,
                       grade_format("%s/1-self", g->work));
        return true;
    }
    int count = 0;
    char **names = part_list_folders(g->submissions, &count);
    if (names == NULL) {
        fprintf(stderr, "grade: cannot read the folder %s: %s\n", g->submissions, strerror(errno));
        return false;
    }
    char out_real[PATH_MAX] = "", real[PATH_MAX];
    if (realpath(g->out, out_real) == NULL)
        out_real[0] = '\0';
    g->subs = grade_alloc((size_t)count * sizeof *g->subs);
    int digits = count < 100 ? 2 : count < 1000 ? 3 : 6;
    for (int k = 0; k < count; k++) {
        char *path = grade_format("%s/%s", g->submissions, names[k]);
        if (realpath(path, real) != NULL && strcmp(real, out_real) == 0)
            continue;
        char *work = grade_format("%s/%0*d-%.40s", g->work, digits, g->sub_count + 1, names[k]);
        for (char *p = strrchr(work, '/') + 1; *p != '\0'; p++)
            if (!isalnum((unsigned char)*p) && *p != '.' && *p != '_' && *p != '-')
                *p = '_';
        add_submission(g, names[k], path, work);
    }
    if (g->sub_count == 0)
        fprintf(stderr, "grade: no submissions in %s: it should hold a folder a student\n",
                g->submissions);
    return g->sub_count > 0;
}
