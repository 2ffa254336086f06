/* grade_build.c: a program handed in, copied, cleared of the build outputs it carries, given canaries and made. */
#include "grade_build.h"

#include <ftw.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "grade_base.h"
#include "grade_path.h"
#include "grade_run.h"
#include "sandbox.h"

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
    RunResult r = run_student(argv, copy, NULL, 600, 0, &(SandboxView){{copy, NULL}, NULL, 0});
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
            !path_same_bytes(path, r->shipped))
            continue;
        char *cp[] = {"cp", "-f", "--", r->canary, (char *)path, NULL}, *canary[] = {r->canary, NULL};
        run_student(cp, NULL, NULL, 60, 0, &(SandboxView){{planting_in, NULL}, canary, 0});
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
    run_student(let, copy, NULL, 60, 0, &(SandboxView){{copy, NULL}, NULL, 0});
    planting = g;
    planting_in = copy;
    nftw(copy, plant_canary, 16, FTW_PHYS);
}

/* Copies submission s into its work folder (cp -P: a link stays a link, never followed out
 * of it), removes the build outputs it carries, puts the references' canaries in place of
 * the copies of the references it holds, and runs make there under the limits; returns the
 * program it built, or NULL with the reason in s->build_message. */
char *build_submission(const Grading *g, Submission *s)
{
    char *copy = grade_format("%s/build", s->work), *log = grade_format("%s/build.log", s->work);
    char *program = grade_format("%s/raytra", copy);
    /* The sandbox sees the submission by its real path, read-only, and the copy. */
    char real[PATH_MAX], *from = realpath(s->path, real) != NULL ? real : s->path;
    char *source[] = {from, NULL};
    char *cp[] = {"cp", "-R", "-P", "--", grade_format("%s/.", from), copy, NULL};
    char *make[] = {"make", NULL};
    bool trouble = false;
    SandboxView own = {{copy, NULL}, NULL, g->disk_limit};
    struct stat st;
    RunResult r = run_student(cp, NULL, log, 600, 0, &(SandboxView){{copy, NULL}, source, g->disk_limit});
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
    s->build_log_tail = run_tail_relative(r.output, g->work);
    return s->build_message != NULL || r.end == RUN_INTERRUPTED ? NULL : program;
}
