/* child.c: a new child made ready to exec: a session, signals, descriptors, environment, limits, folder. */
#include "child.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "sandbox.h"
#include "user.h"

/* The largest file a child may write: an image, or whatever else it writes in its folder. */
#define FILE_LIMIT (1LL << 30)

/* Prepares a new child: a session of its own (no controlling terminal to push input into),
 * the signals as they were (those caught go back to their defaults at exec), stdin from
 * /dev/null, stdout and stderr to the pipe `out`, the limits, the folder (NULL: the
 * grader's); a student's build or run also gets the sandbox's clean environment and a limit
 * on CPU time, the time limit on every core; exits with SANDBOX_EXEC_FAILED when it cannot. */
void child_setup(const char *dir, int out, long long memory_limit, double time_limit,
                 bool student)
{
    setsid();
    /* Should the grader itself be killed, the child dies with it rather than run on. */
    prctl(PR_SET_PDEATHSIG, SIGKILL, 0, 0, 0);
    signal(SIGPIPE, SIG_DFL);
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, NULL);
    int in = open("/dev/null", O_RDONLY);
    if (in < 0 || dup2(in, 0) < 0 || dup2(out, 1) < 0 || dup2(out, 2) < 0)
        _exit(SANDBOX_EXEC_FAILED);
    /* The child keeps neither the grader's files (the pipe's reading end, the output
     * folder's lock) nor the jobserver pipes of a make that runs the grader: every
     * descriptor above stderr is closed. */
    DIR *fds = opendir("/proc/self/fd");
    for (struct dirent *e; fds != NULL && (e = readdir(fds)) != NULL;)
        if (atoi(e->d_name) > 2 && atoi(e->d_name) != dirfd(fds))
            close(atoi(e->d_name));
    if (fds == NULL || closedir(fds) != 0)
        _exit(SANDBOX_EXEC_FAILED);
    /* Before the limits, which leave a grader built with AddressSanitizer no room to allocate. */
    if (student)
        sandbox_environment(dir);
    /* Soft and hard, so that the child cannot raise them again; should the grader's own hard
     * limit be lower, setrlimit fails and that one stays. */
    setrlimit(RLIMIT_CORE, &(struct rlimit){0, 0});
    setrlimit(RLIMIT_FSIZE, &(struct rlimit){FILE_LIMIT, FILE_LIMIT});
    user_limit_processes();
    if (memory_limit > 0)
        setrlimit(RLIMIT_AS, &(struct rlimit){(rlim_t)memory_limit, (rlim_t)memory_limit});
    rlim_t cpu = (rlim_t)(time_limit * (double)sysconf(_SC_NPROCESSORS_ONLN)) + 5;
    if (student && time_limit > 0)
        setrlimit(RLIMIT_CPU, &(struct rlimit){cpu, cpu + 5});
    /* What a student's program writes, its group (the grader's, with --run-as) reads; it
     * runs at a lower priority than the grader, whose sweeps outrun a loop of forks. */
    if (student) {
        umask(027);
        setpriority(PRIO_PROCESS, 0, 10);
    }
    if (dir != NULL && chdir(dir) != 0) {
        sandbox_fail("cannot enter '%s': %s", dir, strerror(errno));
        _exit(SANDBOX_EXEC_FAILED);
    }
}
