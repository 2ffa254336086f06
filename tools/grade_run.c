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

/* SIGCHLD alone: held back by the grader, for the wait loop to wait for. */
static sigset_t sigchld;

/* Makes SIGINT, SIGTERM and SIGHUP (the terminal going away) requests to stop, which the
 * wait loop polls; holds SIGCHLD back for it to wait for; and makes the grader the parent
 * of any process a child leaves behind (a subreaper), so that it can end those too. */
void run_init(void)
{
    stop_install();
    signal(SIGHUP, stop_request);
    /* With its output piped into head, the grader must not die before ending a child. */
    signal(SIGPIPE, SIG_IGN);
    sigemptyset(&sigchld);
    sigaddset(&sigchld, SIGCHLD);
    sigprocmask(SIG_BLOCK, &sigchld, NULL);
#ifdef __linux__
    prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0);
#endif
}

/* Waits until a child ends (SIGCHLD), a signal asks to stop, or `seconds` pass. */
static void wait_for_signal(double seconds)
{
    struct timespec t = {(time_t)seconds, (long)((seconds - (double)(time_t)seconds) * 1e9)};
    sigtimedwait(&sigchld, NULL, &t);
}

/* Prepares a new child: its own process group, the signals as they were (those caught go
 * back to their defaults at exec), stdin from /dev/null, output to the log (NULL: /dev/null),
 * the limits, the folder (NULL: the grader's); exits with EXEC_FAILED when it cannot. */
static void child_setup(const char *dir, const char *log, long long memory_limit)
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
    int out = log != NULL ? open(log, flags, 0644) : open("/dev/null", O_WRONLY);
    if (in < 0 || out < 0 || dup2(in, 0) < 0 || dup2(out, 1) < 0 || dup2(out, 2) < 0)
        _exit(EXEC_FAILED);
    /* Nor does the child keep the grader's files, or the jobserver pipes of a make that
     * runs the grader: every descriptor above stderr is closed. */
    DIR *fds = opendir("/proc/self/fd");
    for (struct dirent *e; fds != NULL && (e = readdir(fds)) != NULL;)
        if (atoi(e->d_name) > 2 && atoi(e->d_name) != dirfd(fds))
            close(atoi(e->d_name));
    if (fds == NULL || closedir(fds) != 0)
        _exit(EXEC_FAILED);
    /* Soft and hard, so that the child cannot raise them again; should the grader's own hard
     * limit be lower, setrlimit fails and that one stays. */
    setrlimit(RLIMIT_CORE, &(struct rlimit){0, 0});
    setrlimit(RLIMIT_FSIZE, &(struct rlimit){FILE_LIMIT, FILE_LIMIT});
    if (memory_limit > 0)
        setrlimit(RLIMIT_AS, &(struct rlimit){(rlim_t)memory_limit, (rlim_t)memory_limit});
    /* make hands its flags and jobserver to sub-makes through these: a student's make is
     * not a sub-make of the one that may be running the grader. */
    static const char *const make_vars[] = {"MAKEFLAGS", "MFLAGS",    "GNUMAKEFLAGS",
                                            "MAKELEVEL", "MAKEFILES", "MAKEOVERRIDES"};
    for (size_t k = 0; k < sizeof make_vars / sizeof make_vars[0]; k++)
        unsetenv(make_vars[k]);
    if (dir != NULL && chdir(dir) != 0) {
        grade_fail("cannot enter '%s': %s", dir, strerror(errno));
        _exit(EXEC_FAILED);
    }
}

/* Ends and reaps what the last child left running outside its group, which the subreaper
 * made the grader's children (an unreaped pid is never reused); gives up, warning, after
 * two seconds of a fork bomb. */
static void end_stragglers(void)
{
    char path[300], text[512];
    double give_up = clock_now() + 2;
    for (;;) {
        pid_t p;
        while ((p = waitpid(-1, NULL, WNOHANG)) > 0)
            continue;
        if (p < 0) /* ECHILD: no process is left */
            return;
        if (clock_now() > give_up) {
            fprintf(stderr, "grade: warning: some processes a submission started would not end\n");
            return;
        }
        DIR *d = opendir("/proc");
        for (struct dirent *e; d != NULL && (e = readdir(d)) != NULL;) {
            snprintf(path, sizeof path, "/proc/%s/stat", e->d_name);
            FILE *f = isdigit((unsigned char)e->d_name[0]) ? fopen(path, "r") : NULL;
            size_t n = f != NULL ? fread(text, 1, sizeof text - 1, f) : 0;
            if (f != NULL)
                fclose(f);
            text[n] = '\0';
            /* "pid (name) state ppid ...": the name may hold spaces and parentheses. */
            const char *name_end = strrchr(text, ')');
            long ppid;
            if (name_end != NULL && sscanf(name_end + 1, " %*c %ld", &ppid) == 1 &&
                ppid == (long)getpid())
                kill((pid_t)atol(e->d_name), SIGKILL);
        }
        if (d != NULL)
            closedir(d);
        wait_for_signal(0.005);
    }
}

/* Runs argv (a program found on PATH) in a child as child_setup prepares it, with at most
 * time_limit seconds and memory_limit bytes (0: no limit), killing its group at the limit
 * or on a stop request; then reaps it and everything it left behind. */
RunResult run_program(char *const argv[], const char *dir, const char *log, double time_limit,
                      long long memory_limit)
{
    double start = clock_now();
    pid_t pid = fork();
    if (pid < 0)
        return (RunResult){.end = RUN_NOT_RUN, .status = errno};
    if (pid == 0) {
        child_setup(dir, log, memory_limit);
        execvp(argv[0], argv);
        grade_fail("cannot run '%s': %s", argv[0], strerror(errno));
        _exit(EXEC_FAILED);
    }
    /* Also here, so that the group exists before any kill, whichever runs first. */
    setpgid(pid, pid);
    RunResult r = {.end = RUN_EXITED};
    siginfo_t info = {0};
    /* WNOWAIT leaves the child a zombie: its pid, its group's id, stays reserved. */
    while (waitid(P_PID, (id_t)pid, &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == 0) {
        double left = time_limit - (clock_now() - start);
        if (stop_requested() || (time_limit > 0 && left <= 0)) {
            r.end = stop_requested() ? RUN_INTERRUPTED : RUN_TIMED_OUT;
            break;
        }
        /* A stray SIGCHLD (of a process left behind) only makes the loop look again. */
        wait_for_signal(time_limit > 0 && left < 0.1 ? left : 0.1);
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
    r.ok = r.end == RUN_EXITED && r.status == 0;
    end_stragglers();
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
