/* grade_submission.c: the class listed; each submission graded: its program built and run, or its images read. */
#include "grade_submission.h"

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

#include "contain.h"
#include "grade_base.h"
#include "grade_build.h"
#include "grade_bvh.h"
#include "grade_judge.h"
#include "grade_path.h"
#include "grade_run.h"
#include "grade_verdict.h"
#include "sandbox.h"
#include "stop.h"

/* Grades render k of a submission of images: finds the image (judge_image_path) and judges it. */
static void grade_image(const Grading *g, Submission *s, int k)
{
    judge_file(g, s, k, judge_image_path(g, s, k),
               grade_format("no %s.png, .pfm or .exr in the submission", g->renders[k].name));
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

/* Returns the real path of the regular file at path, or NULL. */
static char *real_file(const char *path)
{
    char real[PATH_MAX];
    return realpath(path, real) != NULL && path_kind(real) == S_IFREG
               ? grade_format("%s", real)
               : NULL;
}

/* Returns what a render of the scene at `scene` (from the folder run_dir) reads, which its
 * sandbox shows read-only, NULL-ended: `also` (the program's folder), the scene, and each
 * mesh it names on a `w` line, found as raytra finds it (docs/scene-format.md): beside the
 * scene, in each folder above, then in run_dir. A mesh found nowhere is left out: raytra
 * then says it is missing. */
static char **scene_files(const char *scene, const char *run_dir, char *also)
{
    const char *at = scene[0] == '/' ? scene : grade_format("%s/%s", run_dir, scene);
    char *real = real_file(at);
    size_t n = 0, room = 8;
    char **files = grade_alloc(room * sizeof *files);
    files[n++] = also;
    if (real == NULL)
        return files;
    files[n++] = real;
    FILE *f = fopen(real, "r");
    char line[4096];
    while (f != NULL && fgets(line, sizeof line, f) != NULL) {
        char *p = line + strspn(line, " \t");
        if (p[0] != 'w' || (p[1] != ' ' && p[1] != '\t'))
            continue;
        p += 1 + strspn(p + 1, " \t");
        p[strcspn(p, "\r\n")] = '\0';
        for (size_t end = strlen(p); end > 0 && (p[end - 1] == ' ' || p[end - 1] == '\t');)
            p[--end] = '\0';
        char *dir = grade_format("%s", real), *found = p[0] == '/' ? real_file(p) : NULL;
        for (char *slash; p[0] != '/' && found == NULL && (slash = strrchr(dir, '/')) != NULL;) {
            *slash = '\0';
            found = real_file(grade_format("%s/%s", dir, p));
        }
        if (found == NULL && p[0] != '/')
            found = real_file(grade_format("%s/%s", run_dir, p));
        if (found != NULL && n + 2 > room) {
            char **grown = grade_alloc((room *= 2) * sizeof *grown);
            memcpy(grown, files, n * sizeof *files);
            files = grown;
        }
        if (found != NULL)
            files[n++] = found;
    }
    if (f != NULL)
        fclose(f);
    files[n] = NULL;
    return files;
}

/* Grades render k of a submission that is a program: runs it on the scene under the
 * limits, in a scratch folder, and judges how it ended and what it wrote. */
static void run_scene(const Grading *g, Submission *s, int k)
{
    const Render *r = &g->renders[k];
    SceneResult *res = &s->results[k];
    char *log = grade_format("%s/%s.log", s->work, r->name);
    char *image = judge_image_path(g, s, k);
    /* The program and its image are named from the run folder, so that neither what it
     * prints nor its command line depends on where the work folder is (a shard's, merged). */
    r->argv[0] = "../build/raytra";
    r->argv[2] = grade_format("../images/%s", r->image);
    char *dir = grade_format("%s/run", s->work);
    /* The sandbox: the run and images folders to write; the build and the scene to read. */
    char **files = scene_files(r->argv[1], dir, grade_format("%s/build", s->work));
    SandboxView view = {{dir, grade_format("%s/images", s->work), NULL}, files, g->disk_limit};
    /* A hidden scene's files are the grader's alone but while they are rendered. */
    show_hidden(g, files, 0644);
    RunResult run = run_student(r->argv, dir, log, g->time_limit, g->memory_limit, &view);
    show_hidden(g, files, 0600);
    res->seconds = run.seconds;
    res->log_tail = run_tail_relative(run.output, g->work);
    res->command = run_command_line(r->argv, NULL);
    char *how = run_describe(&run);
    struct stat st;
    bool wrote = lstat(image, &st) == 0, exited = run.end == RUN_EXITED;
    bool failed = run.end == RUN_KILLED || (exited && run.status != 0);
    /* The kernel's out-of-memory killer sends SIGKILL; the grader's own kills are timeouts. */
    if (failed &&
        (says_out_of_memory(res->log_tail) || (run.end == RUN_KILLED && run.status == SIGKILL)))
        verdict_set(res, VERDICT_OUT_OF_MEMORY, "ran out of memory (%s; memory limit %s)", how,
                    grade_size_text(g->memory_limit));
    else if (run.end == RUN_TIMED_OUT)
        verdict_set(res, VERDICT_TIMEOUT, "did not finish within %g s", g->time_limit);
    else if (run.end == RUN_OVER_DISK)
        verdict_set(res, VERDICT_ERROR, "wrote more than %s, the disk limit, or filled the disk: "
                    "stopped, and what it wrote removed", grade_size_text(g->disk_limit));
    else if (run.end == RUN_KILLED)
        verdict_set(res, VERDICT_CRASHED, "%s", how);
    else if (run.end == RUN_NOT_RUN)
        verdict_set(res, VERDICT_ERROR, "the grader could not start the program (%s)", how);
    else if (!wrote && failed)
        verdict_set(res, VERDICT_ERROR, "ended with %s and wrote no image", how);
    else if (exited)
        judge_file(g, s, k, image, grade_format("ended normally but wrote no %s", r->image));
    /* A right image from a BVH that breaks part 1.4's rules fails all the same: its report,
     * the last line printed, is in the log's tail (run.output is imgdiff's by now). */
    if (exited && !failed)
        bvh_judge(res, res->log_tail);
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
    if (trouble == NULL && contain_users() > 0 && chmod(s->work, 0711) != 0)
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
 * why not; counts the verdicts and tells them on f ("5 scenes: 4 pass, 1 timeout", the line
 * left for the caller to end); false when grading must stop (interrupted). */
static bool grade_one(const Grading *g, Submission *s, const char *trouble, FILE *f)
{
    s->results = grade_alloc((size_t)g->render_count * sizeof *s->results);
    char *program =
        trouble == NULL && s->program && s->link == NULL ? build_submission(g, s) : NULL;
    for (int k = 0; k < g->render_count && !stop_requested(); k++) {
        /* A folder that is a link (to a classmate's) is not a submission of its own. */
        if (trouble != NULL)
            verdict_set(&s->results[k], VERDICT_ERROR,
                        "the grader could not make its work "
                        "folder: %s",
                        trouble);
        else if (s->link != NULL)
            verdict_set(&s->results[k], VERDICT_LINK,
                        "the submission's folder is a symbolic link to %s", s->link);
        else if (!s->program)
            grade_image(g, s, k);
        else if (program != NULL)
            run_scene(g, s, k);
        else
            verdict_set(&s->results[k], VERDICT_BUILD_FAILED, "%s", s->build_message);
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
        fprintf(f, "BUILD FAILED: %s", s->build_message);
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
    return true;
}

/* Grades submission s, telling the progress on f: its name and kind, then how its scenes
 * fared ("5 scenes: 4 pass, 1 timeout"), a line the caller ends (with how far the class
 * is); false when grading must stop (interrupted). */
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
    if (contain_users() > 0)
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
