/* grade_run.c: a program run under limits (sandbox/spawn.c), its log; how it ended and what it printed, in words. */
#include "grade_run.h"

#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "grade_base.h"
#include "spawn.h"
#include "stop.h"
#ifdef __linux__
#include <sys/prctl.h>
#endif

/* The end of a program's output that the report shows: its last lines, each cut to a
 * length. Counted in lines, so that a time printed wider in one run than in another ("in
 * 0.1 s", "in 10.2 s") does not change which lines are shown. */
#define TAIL_LINES 24
#define TAIL_LINE_BYTES 200

/* Makes SIGINT, SIGTERM and SIGHUP (the terminal going away) requests to stop, which the
 * wait loop polls; holds SIGCHLD back for it to wait for; makes the grader the parent of
 * any process a child leaves behind (a subreaper), so that it can end those too; and takes
 * from the environment its children inherit what a make running the grader hands on. */
void run_init(void)
{
    stop_install();
    signal(SIGHUP, stop_request);
    /* With its output piped into head, the grader must not die before ending a child. */
    signal(SIGPIPE, SIG_IGN);
    sigset_t sigchld;
    sigemptyset(&sigchld);
    sigaddset(&sigchld, SIGCHLD);
    sigprocmask(SIG_BLOCK, &sigchld, NULL);
#ifdef __linux__
    prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0);
#endif
    /* make hands its flags and jobserver to sub-makes through these: a make the grader runs
     * (a part's references) is not a sub-make of the one that may be running the grader. */
    static const char *const make_vars[] = {"MAKEFLAGS", "MFLAGS",    "GNUMAKEFLAGS",
                                            "MAKELEVEL", "MAKEFILES", "MAKEOVERRIDES"};
    for (size_t k = 0; k < sizeof make_vars / sizeof make_vars[0]; k++)
        unsetenv(make_vars[k]);
}

/* Writes the log at path anew: the command line, the output, how the run ended. Whatever a
 * program left at the path is removed first, never followed (O_EXCL, O_NOFOLLOW). */
static void write_log(const char *path, char *const argv[], const char *dir, const RunResult *r)
{
    struct stat st;
    if (lstat(path, &st) == 0 && !S_ISDIR(st.st_mode))
        unlink(path);
    int fd = open(path, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    FILE *f = fd >= 0 ? fdopen(fd, "w") : NULL;
    if (f != NULL)
        fprintf(f, "$ %s\n%s%s[grade: %s; it ran %.2f s]\n", run_command_line(argv, dir), r->output,
                r->output[0] == '\0' || r->output[strlen(r->output) - 1] == '\n' ? "" : "\n",
                run_describe(r), r->seconds);
    if (f == NULL || fclose(f) != 0)
        fprintf(stderr, "grade: warning: cannot write the log %s: %s\n", path, strerror(errno));
    if (f == NULL && fd >= 0)
        close(fd);
}

/* Runs argv as spawn_run does (a student's with view, in the sandbox), a stop request
 * stopping it, and writes the log at path `log` (NULL: none). */
static RunResult run_child(char *const argv[], const char *dir, const char *log,
                           double time_limit, long long memory_limit, const SandboxView *view)
{
    RunResult r = spawn_run(argv, dir, time_limit, memory_limit, view, stop_requested);
    if (log != NULL)
        write_log(log, argv, dir, &r);
    return r;
}

/* Runs a program of the grader's own (imgdiff, cp, sh) as run_child does. */
RunResult run_program(char *const argv[], const char *dir, const char *log, double time_limit,
                      long long memory_limit)
{
    return run_child(argv, dir, log, time_limit, memory_limit, NULL);
}

/* Runs a student's build or program as run_child does, in the sandbox with what view lets it
 * reach: with --run-as, as the student's user. */
RunResult run_student(char *const argv[], const char *dir, const char *log, double time_limit,
                      long long memory_limit, const SandboxView *view)
{
    RunResult r = run_child(argv, dir, log, time_limit, memory_limit, view);
    if (r.end != RUN_OVER_DISK)
        return r;
    /* What it wrote is removed, so that the disk is there for the rest of the class. */
    r.output = grade_format("%s", r.output);
    for (int k = 0; view->write[k] != NULL; k++) {
        char *empty[] = {"find", (char *)view->write[k], "-mindepth", "1", "-delete", NULL};
        run_child(empty, NULL, NULL, 600, 0, &(SandboxView){{view->write[k], NULL}, NULL, 0});
    }
    return r;
}

/* Returns how a run ended: "exit status 2", "killed by signal 11 (Segmentation fault)". */
char *run_describe(const RunResult *r)
{
    switch (r->end) {
    case RUN_EXITED: return grade_format("exit status %d", r->status);
    case RUN_KILLED:
        return grade_format("killed by signal %d (%s)", r->status, strsignal(r->status));
    case RUN_TIMED_OUT: return grade_format("still running after %.0f s", r->seconds);
    case RUN_NOT_RUN: return grade_format("not started: %s", strerror(r->status));
    case RUN_OVER_DISK:
        return "stopped: it wrote more than its disk limit (--disk-limit), or filled the disk";
    default: return "interrupted";
    }
}

/* Returns word as the shell reads it: as it is when it holds only safe characters, else in
 * single quotes, each of its own written '\''. */
char *run_quote(const char *word)
{
    if (word[0] != '\0' && strspn(word, "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                        "0123456789_-./=:,+@%") == strlen(word))
        return grade_format("%s", word);
    char *out = grade_alloc(4 * strlen(word) + 3), *o = out;
    *o++ = '\'';
    for (const char *w = word; *w != '\0'; w++) {
        if (*w == '\'')
            o = stpcpy(o, "'\\''");
        else
            *o++ = *w;
    }
    strcpy(o, "'");
    return out;
}

/* Returns the command line of a run as a shell would take it: "cd DIR && PROGRAM ARGS",
 * every word quoted as it needs, so that it can be pasted to run the same again. */
char *run_command_line(char *const argv[], const char *dir)
{
    char *line = dir != NULL ? grade_format("cd %s &&", run_quote(dir)) : "";
    for (char *const *a = argv; *a != NULL; a++)
        line = grade_format("%s%s%s", line, line[0] != '\0' ? " " : "", run_quote(*a));
    return line;
}

/* Returns the last TAIL_LINES lines of a program's output, each cut to TAIL_LINE_BYTES,
 * "[...]" for what was cut; NULL when it printed nothing but blanks. */
char *run_tail(const char *output)
{
    size_t n = strlen(output);
    while (n > 0 && isspace((unsigned char)output[n - 1]))
        n--;
    /* Back to just after the TAIL_LINES-th line break from the end, or to the start. */
    size_t from = n;
    for (int lines = 0; from > 0 && (output[from - 1] != '\n' || ++lines < TAIL_LINES);)
        from--;
    char *text = grade_alloc(n - from + 6 * TAIL_LINES + 8), *t = text;
    if (from > 0)
        t = stpcpy(t, "[...]\n");
    for (const char *line = output + from, *end = output + n; line < end;) {
        size_t len = strcspn(line, "\n");
        len = len < (size_t)(end - line) ? len : (size_t)(end - line);
        memcpy(t, line, len < TAIL_LINE_BYTES ? len : TAIL_LINE_BYTES);
        t += len < TAIL_LINE_BYTES ? len : TAIL_LINE_BYTES;
        t = stpcpy(t, len > TAIL_LINE_BYTES ? "[...]" : "");
        line += len;
        if (line < end)
            *t++ = *line++;
    }
    *t = '\0';
    return n > 0 ? text : NULL;
}

/* Returns the end of a program's output (run_tail) with the path of the work folder `work`
 * written "work" (as in a compiler's -I flags, or a program naming its folder), so that
 * what the report shows does not depend on where the work folder is: a shard's, merged. */
char *run_tail_relative(const char *output, const char *work)
{
    size_t len = strlen(work);
    char *text = grade_alloc(strlen(output) + 1), *t = text;
    for (const char *p = output; *p != '\0';)
        if (strncmp(p, work, len) == 0)
            t = stpcpy(t, "work"), p += len;
        else
            *t++ = *p++;
    return run_tail(text);
}
