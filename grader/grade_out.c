/* grade_out.c: the output folder (--out), made when it may serve and locked, and its work folder made anew. */
#include "grade_out.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "contain.h"
#include "grade_base.h"
#include "grade_path.h"
#include "grade_run.h"
#include "sandbox.h"

/* Returns why the output folder, at `out` (its real path), cannot serve: it is the
 * submissions folder, or inside a submission (which is copied to be built, and would copy
 * itself), or the submissions are inside its work folder (which is made anew); NULL when it
 * can. A folder of a class that is the output folder is not graded (submission_list). */
static char *out_refusal(const Grading *g, const char *out)
{
    char subs[PATH_MAX];
    if (realpath(g->submissions, subs) == NULL)
        return grade_format("cannot find the folder %s: %s", g->submissions, strerror(errno));
    size_t len = strlen(subs), out_len = strlen(out);
    const char *rest = strncmp(out, subs, len) == 0 && (out[len] == '/' || len == 1)
                           ? out + len + (len > 1)
                           : NULL;
    char *work = grade_format("%s/work", out);
    if (strcmp(out, subs) == 0)
        return grade_format("the output folder %s is the submissions folder: its work folder would "
                            "be graded as a student's; choose an --out outside it",
                            g->out);
    if (rest != NULL && g->shard_n > 0)
        return grade_format("the output folder %s of a shard is inside the class %s: the "
                            "other shards would list it as a submission; choose an --out "
                            "outside it",
                            g->out, g->submissions);
    if (rest != NULL && (g->self || strchr(rest, '/') != NULL))
        return grade_format(
            "the output folder %s is inside the submission %s, which grade copies "
            "to build it; choose an --out outside it",
            g->out, g->self ? g->submissions : grade_format("%.*s", (int)strcspn(rest, "/"), rest));
    if (strncmp(subs, work, out_len + 5) == 0 &&
        (subs[out_len + 5] == '/' || subs[out_len + 5] == 0))
        return grade_format("the submissions folder %s is within %s, which grade makes anew; "
                            "choose another --out",
                            g->submissions, work);
    return NULL;
}

/* Locks the output folder for this run: an exclusive flock on OUT/.grade-lock, held until
 * the grader exits (its descriptor stays open, closed in every child), so that a second run
 * on the same --out refuses rather than mixing its work with this one's; false (reported). */
static bool lock_out(const Grading *g, const char *out)
{
    char *path = grade_format("%s/.grade-lock", out);
    int fd = open(path, O_RDWR | O_CREAT | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC, 0666);
    if (fd < 0)
        return grade_fail("cannot open the lock file %s: %s", path, strerror(errno));
    if (flock(fd, LOCK_EX | LOCK_NB) == 0)
        return true;
    int err = errno;
    close(fd);
    return err == EWOULDBLOCK
               ? grade_fail("%s is in use: another grade is writing into it (it holds %s); wait "
                            "for it to end, or choose another --out",
                            g->out, path)
               : grade_fail("cannot lock %s: %s", path, strerror(err));
}

/* Has each student's user make what it left in folder (a work folder of an earlier run)
 * writable by all, for the grader to remove it, the submissions' folders, closed once
 * graded, opened to them first; nothing without --run-as. */
void out_release(const char *folder)
{
    int count = 0, users = contain_users();
    char **names = users > 0 ? path_list_folders(folder, &count) : NULL;
    for (int k = 0; k < count; k++)
        chmod(grade_format("%s/%s", folder, names[k]), 0711);
    char *chmod[] = {"chmod", "-R", "a+rwX", "--", (char *)folder, NULL};
    for (int k = 0; k < users; k++) {
        contain_use_slot(k);
        run_student(chmod, NULL, NULL, 600, 0, &(SandboxView){{folder, NULL}, NULL, 0});
    }
    contain_use_slot(0);
}

/* Makes the work folder g->work anew (an earlier one is removed, links never followed),
 * marked as grade's; false (reported) when it cannot. */
static bool make_work(const Grading *g)
{
    struct stat st;
    /* chmod first: a student's build may have left folders read-only; with --run-as, its
     * users make their files in the work folder the grader's to remove. */
    if (lstat(g->work, &st) == 0)
        out_release(g->work);
    char *anew[] = {"sh", "-c",
                    "chmod -R u+rwX -- \"$1\"; rm -rf -- \"$1\" && mkdir -- \"$1\" "
                    "\"$1/references\" \"$1/canaries\" && chmod 700 -- \"$1/references\" && echo \"grade's work folder: each run of grade with this "
                    "--out, but one with --only, removes it and makes it anew.\" "
                    ">\"$1/.made-by-grade\"",
                    "sh", g->work, NULL};
    return run_program(anew, NULL, NULL, 600, 0).ok ||
           grade_fail("cannot make the work folder %s anew", g->work);
}

/* Makes OUT (grading-PART by default), when it may serve, and locks it; makes OUT/work anew,
 * an absolute path as students' programs run elsewhere, removing only a work folder that an
 * earlier run marked; with --only, keeps the work folder of the grading OUT holds. */
bool out_prepare(Grading *g)
{
    char real[PATH_MAX];
    struct stat st;
    g->out = g->out != NULL ? g->out : grade_format("grading-%s", g->part);
    bool made = path_kind(g->out) != S_IFDIR;
    if (made && g->only != NULL)
        return grade_fail("--only: no folder %s: --only regrades students into the grading "
                          "of a class there; grade the whole class into it first",
                          g->out);
    if ((made && !path_make_folder(g->out)) || realpath(g->out, real) == NULL)
        return false;
    char *refusal = g->merging ? NULL : out_refusal(g, real);
    if (refusal != NULL) {
        if (made)
            rmdir(g->out);
        return grade_fail("%s", refusal);
    }
    g->work = grade_format("%s/work", real);
    if (!lock_out(g, real))
        return false;
    /* The results go before the work does: they would name pictures no longer there (a
     * shard's shard.txt, a class's results.txt and the mark of a regrade begun). */
    const char *results[] = {g->shard_n > 0 ? "shard.txt" : "results.txt", ".regrading"};
    for (int k = 0; k < 2 && g->only == NULL; k++)
        if (unlink(grade_format("%s/%s", real, results[k])) != 0 && errno != ENOENT)
            return grade_fail("cannot remove the old results %s/%s: %s", g->out, results[k],
                              strerror(errno));
    /* lstat: a link at the work folder's path is not a work folder grade made. */
    if (lstat(g->work, &st) == 0 &&
        (!S_ISDIR(st.st_mode) || path_kind(grade_format("%s/.made-by-grade", g->work)) == 0))
        return grade_fail("%s exists and was not made by grade: choose another --out", g->work);
    if (g->only != NULL && lstat(g->work, &st) != 0)
        return grade_fail("--only: %s holds no work folder: no grading of a class to regrade "
                          "students into; grade the whole class into it first",
                          g->out);
    if (g->only == NULL && !make_work(g))
        return false;
    /* With --run-as, the students' users cross both to their folders, whatever the umask. */
    return contain_users() == 0 ||
           ((stat(real, &st) == 0 && chmod(real, (st.st_mode & 07777) | 0111) == 0 &&
             chmod(g->work, 0711) == 0) ||
            grade_fail("cannot let the students' users cross %s: %s", real, strerror(errno)));
}
