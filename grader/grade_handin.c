/* grade_handin.c: when each submission was handed in: the time given (--submitted-at), its last git commit, or its newest file's. */
#include "grade_handin.h"

#include <ftw.h>
#include <string.h>
#include <sys/stat.h>

#include "grade_base.h"
#include "grade_run.h"
#include "grade_time.h"

/* Reads the time of the last commit of the git repository that folder dir is (its .git, a
 * folder or a file, is there itself: a repository around it does not count) into *when;
 * false when it is none, or git cannot say. git reads the student's repository with its
 * own configuration set aside where it could run a program (a signature's check, a file
 * system monitor) and no other user's or the system's, as a folder of any owner's. */
static bool git_time(const char *dir, double *when)
{
    char *git = grade_format("%s/.git", dir);
    struct stat st;
    int zone;
    if (lstat(git, &st) != 0 || !(S_ISDIR(st.st_mode) || S_ISREG(st.st_mode)))
        return false;
    char *argv[] = {"env", "GIT_CONFIG_NOSYSTEM=1", "GIT_CONFIG_GLOBAL=/dev/null",
                    "GIT_TERMINAL_PROMPT=0", "git", "-c", "safe.directory=*", "-c",
                    "core.fsmonitor=false", "-c", "log.showSignature=false", "-c",
                    "core.hooksPath=/dev/null", grade_format("--git-dir=%s", git), "log", "-1",
                    "--format=%cI", NULL};
    RunResult run = run_program(argv, NULL, NULL, 30, 0);
    /* The time is the line git prints; a warning may come before it. */
    char *output = grade_format("%s", run.ok ? run.output : "");
    for (char *line = strtok(output, "\n"); line != NULL; line = strtok(NULL, "\n"))
        if (time_parse(line, when, &zone))
            return true;
    return false;
}

/* The newest modification time nftw found so far, and the .git to leave out. */
static double newest;
static const char *skip;

/* Keeps in `newest` the modification time of the file or link at path, unless it lies in
 * the folder `skip`; nftw's callback. */
static int visit(const char *path, const struct stat *st, int kind, struct FTW *at)
{
    (void)at;
    size_t len = strlen(skip);
    bool skipped = strncmp(path, skip, len) == 0 && (path[len] == '\0' || path[len] == '/');
    if ((kind == FTW_F || kind == FTW_SL || kind == FTW_SLN) && !skipped &&
        (double)st->st_mtime > newest)
        newest = (double)st->st_mtime;
    return 0;
}

/* Reads into *when the modification time of the newest file (or link, not followed) in
 * folder dir, its .git aside; false when it holds none. */
static bool newest_file(const char *dir, double *when)
{
    newest = -1;
    skip = grade_format("%s/.git", dir);
    if (nftw(dir, visit, 16, FTW_PHYS) != 0 || newest < 0)
        return false;
    *when = newest;
    return true;
}

/* Finds when each submission was handed in, when a due date makes it count (or
 * --submitted-at gives it): the time given, else its last git commit when the folder is a
 * git repository, else its newest file's; not known for a folder that is a link, or holds
 * no file. */
void handin_find_all(Grading *g)
{
    int zone;
    if (!g->late.due_set && g->submitted_at == NULL)
        return;
    for (int i = 0; i < g->sub_count; i++) {
        Submission *s = &g->subs[i];
        s->time_source = NULL;
        if (g->submitted_at != NULL && time_parse(g->submitted_at, &s->submitted, &zone))
            s->time_source = "given";
        else if (s->link == NULL && git_time(s->path, &s->submitted))
            s->time_source = "git";
        else if (s->link == NULL && newest_file(s->path, &s->submitted))
            s->time_source = "files";
    }
}
