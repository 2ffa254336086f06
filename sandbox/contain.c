/* contain.c: students' runs as users of their own (--run-as), the grader's side, which asks the keeper. */
#define _GNU_SOURCE /* pipe2 */
#include "contain.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include "keeper.h"
#include "sandbox.h"
#include "user.h"

/* The grader's side: the sockets to the keeper, one a student's user, and which this
 * process uses (a worker its job's); count 0 when programs run as the grader's own user. */
static int slot_count, slot_used, sockets[MAX_SLOTS];

/* With --run-as (as root): checks the users, then splits the grader in two. The parent,
 * root, becomes the keeper (keeper_main) and never returns; the child becomes the grader's
 * user for good and returns true, to grade; students' builds and programs (spawn_start)
 * run as the users of run_as, one a job, started and ended by the keeper. Without run_as,
 * returns true and they run as the grader's user, its subreaper's sweep ending them.
 * False (reported) on trouble. */
bool contain_start(const char *run_as, const char *grader_user, int jobs)
{
    User users[MAX_SLOTS], grader;
    if (run_as == NULL)
        return grader_user == NULL || sandbox_fail("--grader-user goes with --run-as");
    if (geteuid() != 0)
        return sandbox_fail("--run-as needs root, to run students' programs as another user");
    if (grader_user == NULL)
        return sandbox_fail("--run-as needs --grader-user: the user the grader runs as");
    if (!user_find(grader_user, &grader))
        return false;
    char list[4096], *save = NULL;
    if (snprintf(list, sizeof list, "%s", run_as) >= (int)sizeof list)
        return sandbox_fail("--run-as names too many users");
    for (char *name = strtok_r(list, ",", &save); name != NULL;
         name = strtok_r(NULL, ",", &save)) {
        if (slot_count == MAX_SLOTS)
            return sandbox_fail("--run-as names more than %d users", MAX_SLOTS);
        if (!user_find(name, &users[slot_count]))
            return false;
        User u = users[slot_count++];
        if (u.uid == 0 || u.uid == grader.uid)
            return sandbox_fail("--run-as %s: a student's user must be neither root nor the "
                                "grader's user",
                                name);
        for (int k = 0; k + 1 < slot_count; k++)
            if (users[k].uid == u.uid)
                return sandbox_fail("--run-as names the user %s twice", name);
        if (user_processes(u.uid, false) > 0)
            return sandbox_fail("the user %s has processes running: --run-as needs users "
                                "that run nothing else, since every process of theirs is ended",
                                name);
    }
    if (slot_count < jobs)
        return sandbox_fail("--jobs %d needs %d users in --run-as, one a job (it names %d)",
                            jobs, jobs, slot_count);
    int pair[MAX_SLOTS][2], keeper_ends[MAX_SLOTS];
    for (int k = 0; k < slot_count; k++)
        if (socketpair(AF_UNIX, SOCK_SEQPACKET | SOCK_CLOEXEC, 0, pair[k]) != 0)
            return sandbox_fail("cannot make a socket: %s", strerror(errno));
    fflush(NULL);
    pid_t keeper = getpid(), child = fork();
    if (child < 0)
        return sandbox_fail("cannot fork: %s", strerror(errno));
    for (int k = 0; k < slot_count; k++) {
        close(pair[k][child == 0 ? 0 : 1]);
        sockets[k] = pair[k][1];
        keeper_ends[k] = pair[k][0];
    }
    if (child > 0)
        keeper_main(users, keeper_ends, slot_count, grader, child);
    /* PR_SET_PDEATHSIG after the ids change, which clears it: the grader ends with the keeper. */
    if (!user_become(grader) || prctl(PR_SET_PDEATHSIG, SIGKILL, 0, 0, 0) != 0 ||
        getppid() != keeper) {
        sandbox_fail("cannot become the grader's user %s: %s", grader_user, strerror(errno));
        _exit(2);
    }
    return true;
}

/* Makes this process (a worker of --jobs) run students' programs as the user of job k. */
void contain_use_slot(int k)
{
    slot_used = k;
}

/* Returns how many students' users the keeper runs programs as, one a job; 0 without
 * --run-as, when programs run as the grader's own user. */
int contain_users(void)
{
    return slot_count;
}

/* Sends request q, with the words of text (len bytes) and the descriptor out (-1: none), to
 * this job's keeper; returns the pipe on which its answer comes (contain_wait), a pipe a
 * request so that an answer to a worker that has ended goes nowhere else; -1 (errno set)
 * when it cannot. */
static int ask(Request q, const char *text, size_t len, int out)
{
    int answer[2];
    if (pipe2(answer, O_CLOEXEC) != 0)
        return -1;
    int fds[2] = {answer[1], out}, count = out < 0 ? 1 : 2;
    char control[CMSG_SPACE(sizeof fds)] = {0};
    struct iovec io[2] = {{&q, sizeof q}, {(char *)text, len}};
    struct msghdr m = {.msg_iov = io, .msg_iovlen = 2, .msg_control = control,
                       .msg_controllen = CMSG_SPACE(count * sizeof(int))};
    struct cmsghdr *c = CMSG_FIRSTHDR(&m);
    *c = (struct cmsghdr){CMSG_LEN(count * sizeof(int)), SOL_SOCKET, SCM_RIGHTS};
    memcpy(CMSG_DATA(c), fds, count * sizeof(int));
    ssize_t sent = sendmsg(sockets[slot_used], &m, MSG_NOSIGNAL);
    close(answer[1]);
    if (sent < 0)
        close(answer[0]); /* errno stays sendmsg's */
    return sent < 0 ? -1 : answer[0];
}

/* Asks the keeper to run argv in dir (NULL: the grader's folder) as this job's student's
 * user, with its output to the descriptor out and the limits; returns the pipe on which the
 * answer comes (contain_wait), or -1 (errno set). */
int contain_run(char *const argv[], const char *dir, int out, long long memory_limit,
                double time_limit)
{
    static char text[1 << 16];
    Request q = {ASK_RUN, 0, memory_limit, time_limit};
    size_t len = 0;
    for (const char *word = dir != NULL ? dir : ""; word != NULL; word = argv[q.argc++]) {
        size_t n = strlen(word) + 1;
        if (len + n > sizeof text)
            return errno = E2BIG, -1;
        memcpy(text + len, word, n);
        len += n;
    }
    q.argc--;
    return ask(q, text, len, out);
}

/* Asks the keeper to end the run going on, and every process of its user. */
void contain_kill(void)
{
    send(sockets[slot_used], &(Request){ASK_KILL, 0, 0, 0}, sizeof(Request), MSG_NOSIGNAL);
}

/* Tells whether the keeper's answer has come on the pipe `answer` (or the keeper is gone). */
bool contain_answered(int answer)
{
    return poll(&(struct pollfd){.fd = answer, .events = POLLIN}, 1, 0) != 0;
}

/* Waits for the keeper's answer on the pipe `answer`, which it closes, once every process of
 * the run's user has ended: true with the run's wait status, false with an errno when it did
 * not start; exits the grader when the keeper could not end them, or is gone. */
bool contain_wait(int answer, int *status)
{
    Answer a;
    ssize_t n;
    while ((n = read(answer, &a, sizeof a)) < 0 && errno == EINTR)
        continue;
    close(answer);
    if (n != (ssize_t)sizeof a || a.how == ANSWER_UNKILLABLE) {
        sandbox_fail(n != (ssize_t)sizeof a
                         ? "the part of the grader that runs students' programs has ended"
                         : "the processes of a student's program would not end");
        _exit(2);
    }
    *status = a.status;
    return a.how == ANSWER_EXITED;
}

/* Makes the folder at path, the grader's, one that this job's student's user may write in
 * (a build's, a program's images and scratch folders): with --run-as, the keeper gives it
 * to that user and the grader's group (keeper_share); false (errno set) when it could not. */
bool contain_share(const char *path)
{
    if (slot_count == 0)
        return true;
    int answer = ask((Request){ASK_SHARE, 0, 0, 0}, path, strlen(path) + 1, -1), status = EIO;
    if (answer < 0 || !contain_wait(answer, &status))
        return false;
    errno = status;
    return status == 0;
}
