/* grade_run.c: a child in its own process group, under limits; how it ended, what it printed. */
#include "grade.h"

#include <ctype.h>
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "imgfile.h"
#include "progress.h"
#include "stop.h"
#ifdef __linux__
#include <sys/prctl.h>
#endif

/* The exit status of a child that could not exec its program (as the shell's). */
#define EXEC_FAILED 127

/* The largest file a child may write: a program printing in a loop must not fill the disk. */
#define FILE_LIMIT (1LL << 30)

/* The end of a program's output that the report shows. */
#define TAIL_BYTES 2048

/* Makes SIGINT, SIGTERM and SIGHUP (the terminal going away) requests to stop, which the
 * wait loop polls; holds SIGCHLD back for it to wait for; and makes the grader the parent
 * of any process a child leaves behind (a subreaper), so that it can end those too. */
void run_init(void)
{
    stop_install();
    signal(SIGHUP, stop_request);
    /* With its output piped into head, the grader must not die before ending a child. */
    signal(SIGPIPE, SIG_IGN);
    sigset_t child;
    sigemptyset(&child);
    sigaddset(&child, SIGCHLD);
    sigprocmask(SIG_BLOCK, &child, NULL);
#ifdef __linux__
    prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0);
#endif
}

/* Waits until a child ends (SIGCHLD), a signal asks to stop, or `seconds` pass. */
static void wait_for_signal(double seconds)
{
    sigset_t child;
    sigemptyset(&child);
    sigaddset(&child, SIGCHLD);
    struct timespec t = {(time_t)seconds, (long)((seconds - (double)(time_t)seconds) * 1e9)};
    sigtimedwait(&child, NULL, &t);
}

/* Closes every file descriptor above stderr, so that a child holds none of the grader's
 * files, nor the jobserver pipes of a make that runs the grader. */
static void close_other_files(void)
{
    DIR *d = opendir("/proc/self/fd");
    if (d == NULL) {
        for (int fd = 3; fd < 1024; fd++)
            close(fd);
        return;
    }
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        int fd = atoi(e->d_name);
        if (fd > 2 && fd != dirfd(d))
            close(fd);
    }
    closedir(d);
}

/* Sets a resource limit, soft and hard, so that the child cannot raise it again; a lower
 * hard limit already set stays, as only root may raise one. */
static void set_limit(int resource, long long value)
{
    struct rlimit r;
    rlim_t v = (rlim_t)value;
    if (getrlimit(resource, &r) != 0)
        return;
    r.rlim_cur = r.rlim_max = r.rlim_max != RLIM_INFINITY && v > r.rlim_max ? r.rlim_max : v;
    setrlimit(resource, &r);
}

/* Prepares a new child: its own process group, stdin from /dev/null, output to the log,
 * the limits, the folder; exits with EXEC_FAILED (why, in the log) when it cannot. The
 * signals the grader catches go back to their defaults at exec; the one it ignores and
 * the one it holds back are given back here. */
static void child_setup(const RunSpec *spec)
{
    setpgid(0, 0);
#ifdef __linux__
    /* Should the grader itself be killed, the child dies with it rather than run on. */
    prctl(PR_SET_PDEATHSIG, SIGKILL, 0, 0, 0);
#endif
    signal(SIGPIPE, SIG_DFL);
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, NULL);
    int in = open("/dev/null", O_RDONLY);
    /* A link or a FIFO a student's program left at the log's path is neither followed
     * nor waited on: the open fails, and the child with it. */
    int flags = O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_NONBLOCK;
    int out = spec->log != NULL ? open(spec->log, flags, 0644) : open("/dev/null", O_WRONLY);
    if (in < 0 || out < 0 || dup2(in, 0) < 0 || dup2(out, 1) < 0 || dup2(out, 2) < 0)
        _exit(EXEC_FAILED);
    close_other_files();
    set_limit(RLIMIT_CORE, 0);
    set_limit(RLIMIT_FSIZE, FILE_LIMIT);
    if (spec->memory_limit > 0)
        set_limit(RLIMIT_AS, spec->memory_limit);
    /* make hands its flags and jobserver to sub-makes through these: a student's make is
     * not a sub-make of the one that may be running the grader. */
    static const char *const make_vars[] = {"MAKEFLAGS", "MFLAGS",    "GNUMAKEFLAGS",
                                            "MAKELEVEL", "MAKEFILES", "MAKEOVERRIDES"};
    for (size_t k = 0; k < sizeof make_vars / sizeof make_vars[0]; k++)
        unsetenv(make_vars[k]);
    if (spec->dir != NULL && chdir(spec->dir) != 0) {
        fprintf(stderr, "grade: cannot enter '%s': %s\n", spec->dir, strerror(errno));
        _exit(EXEC_FAILED);
    }
}

/* Kills every process whose parent is the grader: while no child runs, these are what a
 * child left behind, handed over by the subreaper; an unreaped pid is never reused. */
static void kill_children(void)
{
    DIR *d = opendir("/proc");
    struct dirent *e;
    char path[300], text[512];
    while (d != NULL && (e = readdir(d)) != NULL) {
        snprintf(path, sizeof path, "/proc/%s/stat", e->d_name);
        FILE *f = isdigit((unsigned char)e->d_name[0]) ? fopen(path, "r") : NULL;
        size_t n = f != NULL ? fread(text, 1, sizeof text - 1, f) : 0;
        if (f != NULL)
            fclose(f);
        text[n] = '\0';
        /* "pid (name) state ppid ...": the name may hold spaces and parentheses. */
        char *name_end = strrchr(text, ')');
        long ppid;
        if (name_end != NULL && sscanf(name_end + 1, " %*c %ld", &ppid) == 1 &&
            ppid == (long)getpid())
            kill((pid_t)atol(e->d_name), SIGKILL);
    }
    if (d != NULL)
        closedir(d);
}

/* Ends and reaps whatever the last child left running outside its process group, giving
 * up (with a warning) after two seconds of a fork bomb. */
static void end_stragglers(void)
{
    double give_up = clock_now() + 2;
    for (;;) {
        pid_t p;
        while ((p = waitpid(-1, NULL, WNOHANG)) > 0)
            continue;
        if (p < 0 && errno == ECHILD)
            return;
        if (clock_now() > give_up) {
            fprintf(stderr, "grade: warning: some processes a submission started would not end\n");
            return;
        }
        kill_children();
        wait_for_signal(0.005);
    }
}

/* Waits for child pid, killing its group at the time limit or on a stop request; then
 * reaps it and everything it left behind. */
static RunResult wait_child(pid_t pid, const RunSpec *spec, double start)
{
    RunResult r = {.end = RUN_EXITED};
    for (;;) {
        /* WNOWAIT leaves the child a zombie: its pid, its group's id, stays reserved. */
        siginfo_t info = {0};
        int got = waitid(P_PID, (id_t)pid, &info, WEXITED | WNOHANG | WNOWAIT);
        if ((got == 0 && info.si_pid == pid) || (got < 0 && errno != EINTR))
            break;
        double left = spec->time_limit - (clock_now() - start);
        if (stop_requested() || (spec->time_limit > 0 && left <= 0)) {
            r.end = stop_requested() ? RUN_INTERRUPTED : RUN_TIMED_OUT;
            break;
        }
        /* A stray SIGCHLD (of a process left behind) only makes the loop look again. */
        wait_for_signal(spec->time_limit > 0 && left < 0.1 ? left : 0.1);
    }
    r.seconds = clock_now() - start;
    /* Whatever else of the group still runs (a forked child of the program) ends now. */
    kill(-pid, SIGKILL);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
        continue;
    if (r.end == RUN_EXITED) {
        r.end = WIFSIGNALED(status) ? RUN_KILLED : RUN_EXITED;
        r.status = WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status);
    }
    end_stragglers();
    return r;
}

/* Runs argv (a program found on PATH, with its arguments) in a child under spec's
 * limits; waits for it and all it started. */
RunResult run_program(char *const argv[], const RunSpec *spec)
{
    if (stop_requested())
        return (RunResult){.end = RUN_INTERRUPTED};
    double start = clock_now();
    /* What the grader has buffered must not be written twice, by it and by the child. */
    fflush(NULL);
    pid_t pid = fork();
    if (pid < 0)
        return (RunResult){.end = RUN_NOT_RUN, .status = errno};
    if (pid == 0) {
        child_setup(spec);
        execvp(argv[0], argv);
        fprintf(stderr, "grade: cannot run '%s': %s\n", argv[0], strerror(errno));
        _exit(EXEC_FAILED);
    }
    /* Also here, so that the group exists before any kill, whichever runs first. */
    setpgid(pid, pid);
    return wait_child(pid, spec, start);
}

/* Tells whether a run ended with exit status 0. */
bool run_succeeded(const RunResult *r)
{
    return r->end == RUN_EXITED && r->status == 0;
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
    default: return "interrupted";
    }
}

/* Returns the last lines of the file at path (a program's output), "[...]" first when
 * the start was cut, at a line's; NULL when it is empty or unreadable. */
char *run_log_tail(const char *path)
{
    FILE *f = imgfile_fopen(path);
    long size = f != NULL && fseek(f, 0, SEEK_END) == 0 ? ftell(f) : -1;
    long from = size > TAIL_BYTES ? size - TAIL_BYTES : 0;
    char *text = grade_alloc(TAIL_BYTES + 8);
    size_t n = size > 0 && fseek(f, from, SEEK_SET) == 0 ? fread(text, 1, TAIL_BYTES, f) : 0;
    if (f != NULL)
        fclose(f);
    while (n > 0 && isspace((unsigned char)text[n - 1]))
        n--;
    text[n] = '\0';
    const char *newline = strchr(text, '\n');
    if (from > 0)
        return grade_format("[...]%s", newline != NULL ? newline : text);
    return n > 0 ? text : NULL;
}
