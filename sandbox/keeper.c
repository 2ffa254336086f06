/* keeper.c: root's part with --run-as, the keeper: each run started as a student's user, and ended. */
#define _GNU_SOURCE /* syscall */
#include "keeper.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cgroup.h"
#include "child.h"
#include "sandbox.h"

/* The grader the keeper serves, and its user, whose folders the keeper gives to students'
 * users. */
static pid_t forward_to;
static User grader;

/* The keeper's signal handler: a stop asked of the keeper is passed on to the grader. */
static void forward(int sig)
{
    if (forward_to > 0)
        kill(forward_to, sig);
}

/* Answers a request on its pipe: how its run ended (ANSWER_EXITED with a wait status,
 * ANSWER_NOT_RUN with an errno, ANSWER_UNKILLABLE) or how its folder was shared. An answer
 * to an asker that has ended goes nowhere. */
static void answer(int pipe, int how, int status)
{
    ssize_t written = write(pipe, &(Answer){how, status}, sizeof(Answer));
    (void)written;
}

/* Gives the folder at path, one of the grader's, to user u and the grader's group, mode
 * 2770: the student writes in it, the grader reads it, no classmate enters it (the grader
 * closes it to all once graded); returns 0 or an errno. */
static int keeper_share(User u, const char *path)
{
    int fd = open(path, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    struct stat st;
    int err = fd < 0 || fstat(fd, &st) != 0 ? errno
              : st.st_uid != grader.uid    ? EPERM
              : fchown(fd, u.uid, grader.gid) != 0 || fchmod(fd, 02770) != 0 ? errno
                                                                                : 0;
    if (fd >= 0)
        close(fd);
    return err;
}

/* In a slot's keeper: runs what request q asks for (the words of text: the folder, then
 * argv; its output to out, its answer to the pipe reply) as user u in a cgroup of its own,
 * under the limits, until it ends or another request comes (a kill, taken; a run or the
 * socket's end, left for the next read); then ends every process of u (the cgroup at once,
 * then user_sweep) and answers. False when some would not end. */
static bool keeper_run(int socket, User u, const Request *q, char *text, size_t len, int out,
                       int reply)
{
    char **argv = calloc((size_t)q->argc + 1, sizeof *argv), *dir = text;
    char *p = text + strnlen(text, len) + 1;
    for (int k = 0; argv != NULL && k < q->argc && p < text + len; k++, p += strlen(p) + 1)
        argv[k] = p;
    RunCgroup g = {-1, ""};
    pid_t child = -1;
    errno = argv == NULL || p > text + len || argv[q->argc - 1] == NULL ? EINVAL : 0;
    if (errno == 0 && (g = cgroup_run_open(q->memory_limit), child = fork()) == 0) {
        cgroup_enter(g);
        if (!user_become(u))
            _exit(SANDBOX_EXEC_FAILED);
        child_setup(dir[0] != '\0' ? dir : NULL, out, q->memory_limit, q->time_limit, true);
        execvp(argv[0], argv);
        sandbox_fail("cannot run '%s': %s", argv[0], strerror(errno));
        _exit(SANDBOX_EXEC_FAILED);
    }
    int pidfd = child > 0 ? (int)syscall(SYS_pidfd_open, child, 0) : -1, err = errno, st = 0;
    free(argv);
    struct pollfd wait_for[2] = {{.fd = socket, .events = POLLIN}, {.fd = pidfd, .events = POLLIN}};
    while (pidfd >= 0 && poll(wait_for, 2, -1) < 0 && errno == EINTR)
        continue;
    Request next;
    if (wait_for[0].revents != 0 &&
        recv(socket, &next, sizeof next, MSG_PEEK | MSG_DONTWAIT) == (ssize_t)sizeof next &&
        next.ask == ASK_KILL)
        recv(socket, &next, sizeof next, 0);
    cgroup_run_kill(g);
    bool ended = user_sweep(u);
    while (child > 0 && waitpid(child, &st, 0) < 0 && errno == EINTR)
        continue;
    cgroup_run_end(&g);
    if (pidfd >= 0)
        close(pidfd);
    answer(reply, !ended ? ANSWER_UNKILLABLE : pidfd >= 0 ? ANSWER_EXITED : ANSWER_NOT_RUN,
           pidfd >= 0 ? st : err);
    return ended;
}

/* A slot's keeper: does the requests that come on socket, as user u, one at a time, until
 * the socket's end (the grader and its workers have ended); then ends whatever of u's is
 * left and exits: 0, or 1 when some process of u's would not end. */
static void keeper_slot(int socket, User u)
{
    static char text[1 << 16];
    bool unkillable = false;
    for (;;) {
        Request q = {0};
        int fds[2] = {-1, -1};
        char control[CMSG_SPACE(sizeof fds)];
        struct iovec io[2] = {{&q, sizeof q}, {text, sizeof text - 1}};
        struct msghdr m = {.msg_iov = io, .msg_iovlen = 2, .msg_control = control,
                           .msg_controllen = sizeof control};
        ssize_t n = recvmsg(socket, &m, MSG_CMSG_CLOEXEC);
        if (n < 0 && errno == EINTR)
            continue;
        struct cmsghdr *c = n > 0 ? CMSG_FIRSTHDR(&m) : NULL;
        if (c != NULL && c->cmsg_type == SCM_RIGHTS && c->cmsg_len <= CMSG_LEN(sizeof fds))
            memcpy(fds, CMSG_DATA(c), c->cmsg_len - CMSG_LEN(0));
        if (n <= 0)
            break;
        text[n - (ssize_t)sizeof q > 0 ? n - (ssize_t)sizeof q : 0] = '\0';
        /* fds: the pipe of the answer, then a run's output. */
        if (q.ask == ASK_RUN && fds[1] >= 0 && q.argc > 0 && (size_t)n > sizeof q)
            unkillable |= !keeper_run(socket, u, &q, text, (size_t)n - sizeof q, fds[1], fds[0]);
        else if (q.ask == ASK_SHARE && fds[0] >= 0 && (size_t)n > sizeof q)
            answer(fds[0], ANSWER_EXITED, keeper_share(u, text));
        for (int k = 0; k < 2; k++)
            if (fds[k] >= 0)
                close(fds[k]);
    }
    _exit(user_sweep(u) && !unkillable ? 0 : 1);
}

/* The keeper: root's part, which only starts runs as the students' users and ends them, for
 * the grader, its child, until the grader has ended: a keeper a slot, each reading nothing
 * but the requests on its socket (users[k]'s on sockets[k], of `count`), ends whatever of
 * its user's is left then. Exits as the grader did; grader_pid is the grader's, grader_user
 * its user. */
void keeper_main(const User *users, const int *sockets, int count, User grader_user,
                 pid_t grader_pid)
{
    pid_t slots[MAX_SLOTS];
    grader = grader_user;
    forward_to = grader_pid;
    /* Orphans of students' runs come to the keeper, which reaps them. */
    prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0);
    /* An answer to an asker that has ended goes nowhere, without a SIGPIPE. */
    signal(SIGPIPE, SIG_IGN);
    struct sigaction pass = {.sa_handler = forward, .sa_flags = SA_RESTART};
    sigaction(SIGINT, &pass, NULL);
    sigaction(SIGTERM, &pass, NULL);
    sigaction(SIGHUP, &pass, NULL);
    for (int k = 0; k < count; k++)
        if ((slots[k] = fork()) == 0)
            keeper_slot(sockets[k], users[k]);
    for (int k = 0; k < count; k++)
        close(sockets[k]);
    int grader_status = 0, st;
    bool unkillable = false;
    for (int left = count + 1; left > 0;) {
        pid_t p = wait(&st);
        if (p < 0 && errno != EINTR)
            break;
        left -= p == grader_pid;
        grader_status = p == grader_pid ? st : grader_status;
        for (int k = 0; k < count; k++)
            if (p == slots[k]) {
                left--;
                unkillable |= !WIFEXITED(st) || WEXITSTATUS(st) != 0;
            }
    }
    cgroup_finish();
    if (unkillable)
        sandbox_fail("some processes of a student's user would not end within %d s", SWEEP_GIVE_UP);
    if (WIFSIGNALED(grader_status)) {
        signal(WTERMSIG(grader_status), SIG_DFL);
        raise(WTERMSIG(grader_status));
    }
    _exit(unkillable ? 2 : WEXITSTATUS(grader_status));
}
