/* grade_run.c: a child in its own process group, under limits; how it ended, what it printed. */
#include "grade_run.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "grade.h"
#include "imgfile.h"
#include "progress.h"
#include "stop.h"
#ifdef __linux__
#include <sys/prctl.h>
#endif

/* The log tail keeps at most this much of the end of a program's output. */
#define TAIL_BYTES 2048
#define TAIL_LINES 20

/* Makes SIGINT, SIGTERM and SIGHUP requests to stop, which the wait loop polls to end the
 * child's whole group; holds SIGCHLD back for the wait loop to wait for; and makes the
 * grader the parent of any process a child leaves behind, so that it can end those too. */
void run_init(void)
{
    stop_install();
    /* The terminal going away asks to stop too (stop_request is safe in a handler): a
     * child left hanging would otherwise run on with no grader to end it. */
    struct sigaction sa = {0};
    sa.sa_handler = stop_request;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGHUP, &sa, NULL);
    /* With its output piped into head, the grader must not die before ending a child. */
    sa.sa_handler = SIG_IGN;
    sigaction(SIGPIPE, &sa, NULL);
    sigset_t child;
    sigemptyset(&child);
    sigaddset(&child, SIGCHLD);
    sigprocmask(SIG_BLOCK, &child, NULL);
#ifdef __linux__
    /* A daemon a student's program starts is re-parented to the grader instead of init. */
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
    int own = dirfd(d);
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        int fd = atoi(e->d_name);
        if (fd > 2 && fd != own)
            close(fd);
    }
    closedir(d);
}

/* Sets a resource limit, soft and hard, so that the child cannot raise it again. */
static void set_limit(int resource, long long value)
{
    struct rlimit r;
    if (getrlimit(resource, &r) != 0)
        return;
    /* Only root may raise a hard limit: a lower one already set stays. */
    rlim_t v = (rlim_t)value;
    if (r.rlim_max != RLIM_INFINITY && v > r.rlim_max)
        v = r.rlim_max;
    r.rlim_cur = r.rlim_max = v;
    setrlimit(resource, &r);
}

/* Prepares a new child: its own process group, stdin from /dev/null, output to the log,
 * the limits, the folder; exits with RUN_EXEC_FAILED (why, in the log) when it cannot. */
static void child_setup(const RunSpec *spec)
{
    setpgid(0, 0);
#ifdef __linux__
    /* Should the grader itself be killed, the child dies with it rather than run on. */
    prctl(PR_SET_PDEATHSIG, SIGKILL, 0, 0, 0);
#endif
    struct sigaction sa = {0};
    sa.sa_handler = SIG_DFL;
    sigemptyset(&sa.sa_mask);
    int defaults[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};
    for (size_t k = 0; k < sizeof defaults / sizeof defaults[0]; k++)
        sigaction(defaults[k], &sa, NULL);
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, NULL);
    int in = open("/dev/null", O_RDONLY);
    /* A link or a FIFO a student's program left at the log's path is neither followed
     * nor waited on: the open fails, and the child with it. */
    int flags = O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_NONBLOCK;
    int out = spec->log != NULL ? open(spec->log, flags, 0644) : open("/dev/null", O_WRONLY);
    if (in < 0 || out < 0 || dup2(in, 0) < 0 || dup2(out, 1) < 0 || dup2(out, 2) < 0)
        _exit(RUN_EXEC_FAILED);
    close_other_files();
    set_limit(RLIMIT_CORE, 0);
    set_limit(RLIMIT_FSIZE, RUN_FILE_LIMIT);
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
        _exit(RUN_EXEC_FAILED);
    }
}

/* Returns the parent of process pid, read from /proc/PID/stat; -1 when it cannot tell. */
static long parent_of(long pid)
{
    char path[64], text[512];
    snprintf(path, sizeof path, "/proc/%ld/stat", pid);
    FILE *f = fopen(path, "r");
    if (f == NULL)
        return -1;
    size_t n = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[n] = '\0';
    /* "pid (name) state ppid ...": the name may hold spaces and parentheses. */
    char *name_end = strrchr(text, ')');
    char state;
    long ppid;
    if (name_end == NULL || sscanf(name_end + 1, " %c %ld", &state, &ppid) != 2)
        return -1;
    return ppid;
}

/* Kills every process whose parent is the grader: while a child runs it has no other, so
 * these are what the child left behind, handed over by the subreaper. An unreaped child's
 * pid cannot be reused, so the kill reaches no stranger. */
static void kill_children(void)
{
    DIR *d = opendir("/proc");
    if (d == NULL)
        return;
    long self = (long)getpid();
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        char *end;
        long pid = strtol(e->d_name, &end, 10);
        if (end != e->d_name && *end == '\0' && parent_of(pid) == self)
            kill((pid_t)pid, SIGKILL);
    }
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
        siginfo_t info;
        info.si_pid = 0;
        int got = waitid(P_PID, (id_t)pid, &info, WEXITED | WNOHANG | WNOWAIT);
        if ((got == 0 && info.si_pid == pid) || (got < 0 && errno != EINTR))
            break;
        if (stop_requested()) {
            r.end = RUN_INTERRUPTED;
            break;
        }
        double left = spec->time_limit - (clock_now() - start);
        if (spec->time_limit > 0 && left <= 0) {
            r.end = RUN_TIMED_OUT;
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
    if (r.end == RUN_EXITED && WIFSIGNALED(status)) {
        r.end = RUN_KILLED;
        r.status = WTERMSIG(status);
    } else if (r.end == RUN_EXITED) {
        r.status = WEXITSTATUS(status);
    }
    end_stragglers();
    return r;
}

/* Runs argv (a program found on PATH, with its arguments) or else function(arg) in a
 * child under spec's limits; waits for it and all it started. */
static RunResult run_child(char *const argv[], int (*function)(void *), void *arg,
                           const RunSpec *spec)
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
        if (function != NULL)
            _exit(function(arg));
        execvp(argv[0], argv);
        fprintf(stderr, "grade: cannot run '%s': %s\n", argv[0], strerror(errno));
        _exit(RUN_EXEC_FAILED);
    }
    /* Also here, so that the group exists before any kill, whichever runs first. */
    setpgid(pid, pid);
    return wait_child(pid, spec, start);
}

/* Runs the program argv[0] (found on PATH) with its arguments under spec's limits. */
RunResult run_program(char *const argv[], const RunSpec *spec)
{
    return run_child(argv, NULL, NULL, spec);
}

/* Runs function(arg) in a forked child under spec's limits, so that a crash or a hang
 * in it (on a student's file) cannot take the grader down; its return is the status. */
RunResult run_function(int (*function)(void *), void *arg, const RunSpec *spec)
{
    return run_child(NULL, function, arg, spec);
}

/* Writes into text how a run ended: "exit status 2", "killed by signal 11 (Segmentation
 * fault)", "still running after 60 s". */
void run_describe(const RunResult *r, double limit, char *text, size_t size)
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
char *run_log_tail(const char *path)
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
