/* grade_submission.c: the class's submissions: listed, then built and run or their images found. */
#include "grade_submission.h"

#include <ctype.h>
#include <errno.h>
#include <libgen.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include "grade_compare.h"
#include "grade_part.h"
#include "grade_run.h"
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
        grade_verdict(res, VERDICT_MISSING, "no %s.png, .pfm or .exr in the submission", r->name);
    else if (compare_handed_in(r, res, found))
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
    run_describe(&r, spec.time_limit, how, sizeof how);
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
        run_describe(&r, spec.time_limit, how, sizeof how);
        if (r.end == RUN_TIMED_OUT)
            snprintf(message, size, "make did not finish within %g s", g->build_time_limit);
        else if (r.end != RUN_EXITED || r.status != 0)
            snprintf(message, size, "make failed (%s)", how);
        else if (!grade_is_file(program) || access(program, X_OK) != 0)
            snprintf(message, size,
                     "make succeeded but made no executable raytra beside the "
                     "Makefile");
    }
    s->build_log_tail = run_log_tail(log);
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
    res->log_tail = run_log_tail(log);
    char how[200];
    run_describe(&run, g->time_limit, how, sizeof how);
    struct stat st;
    bool wrote = lstat(image, &st) == 0;
    bool failed = run.end == RUN_KILLED || (run.end == RUN_EXITED && run.status != 0);
    char limit[32];
    grade_size_text(g->memory_limit, limit, sizeof limit);
    /* The kernel's out-of-memory killer sends SIGKILL; the grader's own kills are timeouts. */
    if (failed &&
        (says_out_of_memory(res->log_tail) || (run.end == RUN_KILLED && run.status == SIGKILL)))
        grade_verdict(res, VERDICT_OUT_OF_MEMORY, "ran out of memory (%s; memory limit %s)", how,
                      limit);
    else if (run.end == RUN_TIMED_OUT)
        grade_verdict(res, VERDICT_TIMEOUT, "did not finish within %g s", g->time_limit);
    else if (run.end == RUN_KILLED)
        grade_verdict(res, VERDICT_CRASHED, "%s", how);
    else if (run.end == RUN_NOT_RUN)
        grade_verdict(res, VERDICT_ERROR, "the grader could not start the program (%s)", how);
    else if (run.end == RUN_EXITED && !wrote && run.status != 0)
        grade_verdict(res, VERDICT_ERROR, "ended with %s and wrote no image", how);
    else if (run.end == RUN_EXITED && !wrote)
        grade_verdict(res, VERDICT_MISSING, "ended normally but wrote no %s", r->image);
    else if (run.end == RUN_EXITED && compare_handed_in(r, res, image))
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

/* Grades every render of submission s into s->results and counts the verdicts; false
 * when grading must stop (interrupted, or the grader's own trouble, reported). */
static bool grade_one(const Grading *g, Submission *s)
{
    s->results = grade_alloc((size_t)g->render_count * sizeof *s->results);
    for (int k = 0; k < g->render_count; k++)
        s->results[k].seconds = -1;
    if (!grade_make_folder(s->work, true))
        return false;
    char *program = NULL;
    if (s->program && s->link == NULL) {
        char *images = grade_format("%s/images", s->work);
        char *scratch = grade_format("%s/run", s->work);
        bool ok = grade_make_folder(images, true) && grade_make_folder(scratch, true);
        free(images);
        free(scratch);
        if (!ok)
            return false;
        program = build(g, s);
    }
    for (int k = 0; k < g->render_count && !stop_requested(); k++) {
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
    free(program);
    for (int k = 0; k < g->render_count; k++) {
        s->verdicts[s->results[k].verdict]++;
        s->tally[verdict_info[s->results[k].verdict].tally]++;
    }
    return !stop_requested();
}

/* Prints text to stderr with control characters made '?', so that a folder's name cannot
 * play tricks on the terminal. */
static void print_plain(const char *text)
{
    for (const char *p = text; *p != '\0'; p++)
        fputc((unsigned char)*p < 0x20 || *p == 0x7F ? '?' : *p, stderr);
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
    for (int v = 0; v < VERDICT_COUNT; v++)
        if (s->verdicts[v] > 0) {
            fprintf(stderr, "%s%d ", sep, s->verdicts[v]);
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
            fprintf(stderr, "grading ");
            print_plain(s->name);
            fprintf(stderr, " (%s): %s", s->program ? "program" : "images",
                    s->program ? "building... " : "");
        }
        if (!grade_one(g, s)) {
            if (!g->quiet)
                fputc('\n', stderr);
            return false;
        }
        if (!g->quiet)
            print_tally(g, s);
    }
    return true;
}

/* Returns name with every byte but letters, digits, '.', '_' and '-' made '_', cut to 40
 * bytes: a work folder's name that a student's Makefile or script cannot trip on. */
static char *safe_name(const char *name)
{
    char *safe = grade_format("%.40s", name);
    for (char *p = safe; *p != '\0'; p++)
        if (!isalnum((unsigned char)*p) && *p != '.' && *p != '_' && *p != '-')
            *p = '_';
    return safe;
}

/* Adds the submission in the folder path, named name, with its work folder, to g; takes
 * path and work. */
static void add_submission(Grading *g, const char *name, char *path, char *work)
{
    static const char *const makefiles[] = {"GNUmakefile", "makefile", "Makefile"};
    Submission *s = &g->subs[g->sub_count++];
    *s = (Submission){.name = grade_copy(name), .path = path, .work = work};
    /* It is a program when it holds a Makefile, as make looks for one. */
    for (size_t k = 0; k < sizeof makefiles / sizeof makefiles[0] && !s->program; k++) {
        char *makefile = grade_format("%s/%s", path, makefiles[k]);
        s->program = grade_is_file(makefile);
        free(makefile);
    }
    /* A folder of the class that is a link (to a classmate's) is not graded as one. */
    char target[PATH_MAX];
    ssize_t n = g->self ? -1 : readlink(path, target, sizeof target - 1);
    if (n >= 0)
        s->link = grade_format("%.*s", (int)n, target);
}

/* Lists the submissions: the folders in g->submissions but hidden ones and the output
 * folder, in the order of their names, or with --self the one folder; false (reported)
 * when there are none. */
bool submission_list(Grading *g)
{
    if (g->self) {
        /* One student's folder: it is the one submission, named as the folder. */
        char *copy = grade_copy(g->submissions);
        g->subs = grade_alloc(sizeof *g->subs);
        add_submission(g, basename(copy), copy, grade_format("%s/1-self", g->work));
        return true;
    }
    int count = 0;
    char **names = part_list_folders(g->submissions, &count);
    if (names == NULL) {
        fprintf(stderr, "grade: cannot read the folder %s: %s\n", g->submissions, strerror(errno));
        return false;
    }
    char out_real[PATH_MAX], real[PATH_MAX];
    if (realpath(g->out, out_real) == NULL)
        out_real[0] = '\0';
    g->subs = grade_alloc((size_t)count * sizeof *g->subs);
    int digits = count < 100 ? 2 : count < 1000 ? 3 : 6;
    for (int k = 0; k < count; k++) {
        char *path = grade_format("%s/%s", g->submissions, names[k]);
        if (realpath(path, real) != NULL && strcmp(real, out_real) == 0) {
            free(path);
            continue;
        }
        char *safe = safe_name(names[k]);
        add_submission(g, names[k], path,
                       grade_format("%s/%0*d-%s", g->work, digits, g->sub_count + 1, safe));
        free(safe);
    }
    part_free_names(names, count);
    if (g->sub_count == 0) {
        fprintf(stderr, "grade: no submissions in %s: it should hold a folder a student\n",
                g->submissions);
        return false;
    }
    return true;
}
