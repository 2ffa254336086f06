/* spawn.c: a child started contained (a student's in the sandbox), watched under its limits, and ended with all it left. */
#define _GNU_SOURCE /* waitid's WNOWAIT */
#include "spawn.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <sys/types.h>
#include <unistd.h>

#include "capture.h"
#include "cgroup.h"
#include "child.h"
#include "contain.h"
#include "reap.h"

/* A child on its way: what it execs, and how its end is known. */
typedef struct {
    char **argv;     /* what it execs: the program's words, or bubblewrap's around them */
    bool wrapped;    /* in bubblewrap, which tells a signal N by exiting with 128 + N */
    pid_t pid;       /* this process's child, or 0 when the keeper started it (--run-as) */
    int keeper;      /* the pipe on which the keeper answers, or -1 */
    RunCgroup group; /* its cgroup v2, where it has one of this process's making */
} Spawn;

/* Returns the seconds of a clock that no change of the date moves. */
static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

/* Waits until a child ends (SIGCHLD), a signal asks to stop, or `seconds` pass. */
static void wait_for_signal(double seconds)
{
    struct timespec t = {(time_t)seconds, (long)((seconds - (double)(time_t)seconds) * 1e9)};
    sigset_t sigchld;
    sigemptyset(&sigchld);
    sigaddset(&sigchld, SIGCHLD);
    sigtimedwait(&sigchld, NULL, &t);
}

/* Starts argv (a program found on PATH) in folder dir (NULL: this process's), its output to
 * the descriptor out, as child_setup prepares it, under memory_limit bytes (0: none) and, a
 * student's, time_limit seconds of CPU on every core; a student's (view not NULL) in the
 * sandbox (sandbox_wrap) and a cgroup of its own where there may be one, through the keeper
 * as the student's user with --run-as (contain.c). False (errno set) when it cannot. */
static bool spawn_start(Spawn *s, char *const argv[], const char *dir, int out, double time_limit,
                 long long memory_limit, const SandboxView *view)
{
    bool student = view != NULL, kept = student && contain_users() > 0;
    *s = (Spawn){student ? sandbox_wrap(argv, dir, view, kept) : (char **)argv, false, 0, -1,
                 {-1, ""}};
    if (s->argv == NULL)
        return errno = ENOMEM, false;
    s->wrapped = s->argv != argv;
    /* In namespaces, bubblewrap enters dir itself, inside. */
    const char *enter = s->wrapped ? NULL : dir;
    if (kept)
        s->keeper = contain_run(s->argv, enter, out, memory_limit, time_limit);
    else if (student)
        s->group = cgroup_run_open(memory_limit);
    if (!kept && (s->pid = fork()) == 0) {
        cgroup_enter(s->group);
        child_setup(enter, out, memory_limit, time_limit, student);
        execvp(s->argv[0], s->argv);
        sandbox_fail("cannot run '%s': %s", s->argv[0], strerror(errno));
        _exit(SANDBOX_EXEC_FAILED);
    }
    if (s->pid >= 0 && (!kept || s->keeper >= 0))
        return true;
    int err = errno;
    cgroup_run_end(&s->group);
    if (s->wrapped)
        free(s->argv);
    errno = err;
    return false;
}

/* Tells whether the child, or the run the keeper started, has ended. */
static bool spawn_ended(const Spawn *s)
{
    siginfo_t info = {0};
    /* WNOWAIT leaves the child a zombie: its pid, its group's id, stays reserved. */
    return s->pid == 0 ? contain_answered(s->keeper)
                       : waitid(P_PID, (id_t)s->pid, &info, WEXITED | WNOHANG | WNOWAIT) != 0 ||
                             info.si_pid != 0;
}

/* Ends the run (stop: before it ended by itself) and everything it left behind, and reaps it:
 * through the keeper, which sweeps its user's processes, or as this process's child, its
 * session killed and its strays swept. True with its wait status; false with an errno when
 * the keeper could not start it. */
static bool spawn_end(Spawn *s, bool stop, int *status)
{
    bool ran = true;
    *status = 0;
    if (s->pid == 0) {
        if (stop)
            contain_kill();
        ran = contain_wait(s->keeper, status);
    } else {
        /* Whatever else of the session's group still runs (a forked child of the program)
         * ends now; the child itself too, should it have been killed before its setsid. */
        kill(-s->pid, SIGKILL);
        kill(s->pid, SIGKILL);
        while (waitpid(s->pid, status, 0) < 0 && errno == EINTR)
            continue;
        cgroup_run_end(&s->group);
        reap_strays(NULL, 0);
    }
    if (s->wrapped)
        free(s->argv);
    s->argv = NULL;
    return ran;
}

/* Runs argv (a program found on PATH) in a child as spawn_start starts it, with at most
 * time_limit seconds and memory_limit bytes (0: no limit), killing it at the limit or when
 * stopped() says so; a student's (view not NULL) in the sandbox, also killed past its disk
 * limit; then ends everything it left behind (spawn_end). Its output comes through a pipe,
 * kept in part (Capture). SIGCHLD is best held back (blocked) by the caller. */
RunResult spawn_run(char *const argv[], const char *dir, double time_limit,
                    long long memory_limit, const SandboxView *view, bool (*stopped)(void))
{
    static Capture capture;
    Capture *c = &capture;
    c->head_len = 0;
    c->total = 0;
    int fds[2];
    if (pipe(fds) != 0)
        return (RunResult){.end = RUN_NOT_RUN, .status = errno, .output = ""};
    fcntl(fds[0], F_SETFD, FD_CLOEXEC);
    fcntl(fds[0], F_SETFL, O_NONBLOCK);
    double start = now();
    Spawn child;
    bool started = spawn_start(&child, argv, dir, fds[1], time_limit, memory_limit, view);
    int err = errno, fd = fds[0];
    close(fds[1]);
    if (!started) {
        close(fd);
        return (RunResult){.end = RUN_NOT_RUN, .status = err, .output = ""};
    }
    RunResult r = {.end = RUN_EXITED};
    double disk_looked = start;
    while (!spawn_ended(&child)) {
        double at = now(), left = time_limit - (at - start);
        /* The disk is looked at twice a second: a folder's bytes are counted file by file. */
        bool over_disk = at - disk_looked > 0.5 && sandbox_over_disk(view);
        disk_looked = at - disk_looked > 0.5 ? at : disk_looked;
        if (stopped() || (time_limit > 0 && left <= 0) || over_disk) {
            r.end = stopped() ? RUN_INTERRUPTED
                    : over_disk      ? RUN_OVER_DISK
                                     : RUN_TIMED_OUT;
            break;
        }
        double wait = time_limit > 0 && left < 0.1 ? left : 0.1;
        /* Output wakes the loop, and so do its end (the child's exit closes the pipe) and
         * the keeper's answer; once the output has ended, SIGCHLD does. A stray SIGCHLD
         * only makes the loop look again. */
        struct pollfd p[2] = {{.fd = fd, .events = POLLIN},
                              {.fd = child.keeper, .events = POLLIN}};
        if (fd < 0 && child.keeper < 0)
            wait_for_signal(wait);
        else if (poll(p, 2, (int)(wait * 1000) + 1) > 0 && p[0].revents != 0)
            fd = capture_read(c, fd);
    }
    r.seconds = now() - start;
    int status = 0;
    bool wrapped = child.wrapped;
    if (!spawn_end(&child, r.end != RUN_EXITED, &status) && r.end == RUN_EXITED) {
        r.end = RUN_NOT_RUN;
        r.status = status;
    }
    if (r.end == RUN_EXITED && sandbox_over_disk(view))
        r.end = RUN_OVER_DISK;
    if (r.end == RUN_EXITED) {
        r.end = WIFSIGNALED(status) ? RUN_KILLED : RUN_EXITED;
        r.status = WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status);
    }
    /* bubblewrap tells a program killed by signal N by exiting with 128 + N, as a shell does
     * (and as a program that exits so): taken as the signal. */
    if (r.end == RUN_EXITED && wrapped && r.status > 128 && r.status <= 128 + 64) {
        r.end = RUN_KILLED;
        r.status -= 128;
    }
    r.ok = r.end == RUN_EXITED && r.status == 0;
    /* Everything that could write to the pipe has ended: what it holds is the last. */
    if (fd >= 0 && capture_read(c, fd) >= 0)
        close(fd);
    r.output = capture_text(c);
    return r;
}
