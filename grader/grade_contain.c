/* grade_contain.c: students' runs as users of their own (--run-as), the grader's side, which asks the keeper. */
#include "grade_contain.h"

#include <errno.h>
#include <signal.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <unistd.h>

#include "grade_base.h"
#include "grade_keeper.h"
#include "grade_user.h"

/* The grader's side: the sockets to the keeper, one a student's user, and which this
 * process uses (a worker its job's); count 0 when programs run as the grader's own user. */
static int slot_count, slot_used, sockets[MAX_SLOTS];

/* With --run-as (as root): checks the users, then splits the grader in two. The parent,
 * root, becomes the keeper (keeper_main) and never returns; the child becomes the grader's
 * user for good and returns true, to grade; students' builds and programs (run_student)
 * run as the users of run_as, one a job, started and ended by the keeper. Without run_as,
 * returns true and they run as the grader's user, its subreaper's sweep ending them.
 * False (reported) on trouble. */
bool contain_start(const char *run_as, const char *grader_user, int jobs)
{
    User users[MAX_SLOTS], grader;
    if (run_as == NULL)
        return grader_user == NULL || grade_fail("--grader-user goes with --run-as");
    if (geteuid() != 0)
        return grade_fail("--run-as needs root, to run students' programs as another user");
    if (grader_user == NULL)
        return grade_fail("--run-as needs --grader-user: the user the grader runs as");
    if (!user_find(grader_user, &grader))
        return false;
    char *list = grade_format("%s", run_as);
    for (char *name = strtok(list, ","); name != NULL; name = strtok(NULL, ",")) {
        if (slot_count == MAX_SLOTS)
            return grade_fail("--run-as names more than %d users", MAX_SLOTS);
        if (!user_find(name, &users[slot_count]))
            return false;
        User u = users[slot_count++];
        if (u.uid == 0 || u.uid == grader.uid)
            return grade_fail("--run-as %s: a student's user must be neither root nor the "
                              "grader's user",
                              name);
        for (int k = 0; k + 1 < slot_count; k++)
            if (users[k].uid == u.uid)
                return grade_fail("--run-as names the user %s twice", name);
        if (user_processes(u.uid, false) > 0)
            return grade_fail("the user %s has processes running: --run-as needs users that "
                              "run nothing else, since every process of theirs is ended",
                              name);
    }
    if (slot_count < jobs)
        return grade_fail("--jobs %d needs %d users in --run-as, one a job (it names %d)", jobs,
                          jobs, slot_count);
    int pair[MAX_SLOTS][2], keeper_ends[MAX_SLOTS];
    for (int k = 0; k < slot_count; k++)
        if (socketpair(AF_UNIX, SOCK_SEQPACKET | SOCK_CLOEXEC, 0, pair[k]) != 0)
            return grade_fail("cannot make a socket: %s", strerror(errno));
    fflush(NULL);
    pid_t keeper = getpid(), child = fork();
    if (child < 0)
        return grade_fail("cannot fork: %s", strerror(errno));
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
        grade_fail("cannot become the grader's user %s: %s", grader_user, strerror(errno));
        _exit(2);
    }
    return true;
}

/* Makes this process (a worker of --jobs) run students' programs as the user of job k. */
void contain_use_slot(int k)
{
    slot_used = k;
}

/* Tells whether students' programs run as users of their own, through the keeper. */
bool contain_active(void)
{
    return slot_count > 0;
}

/* Returns how many students' users the keeper runs programs as, one a job; 0 without
 * --run-as. */
int contain_users(void)
{
    return slot_count;
}

/* Asks the keeper to run argv in dir (NULL: the grader's folder) as this job's student's
 * user, with its output to the descriptor out and memory_limit; returns the socket on which
 * the answer comes (contain_wait), or -1 (errno set). */
int contain_run(char *const argv[], const char *dir, int out, long long memory_limit,
                double time_limit)
{
    static char text[1 << 16];
    static long serial;
    Request q = {ASK_RUN, 0, memory_limit, time_limit, (long)getpid(), ++serial};
    size_t len = 0;
    for (const char *word = dir != NULL ? dir : ""; word != NULL; word = argv[q.argc++]) {
        size_t n = strlen(word) + 1;
        if (len + n > sizeof text) {
            errno = E2BIG;
            return -1;
        }
        memcpy(text + len, word, n);
        len += n;
    }
    q.argc--;
    char control[CMSG_SPACE(sizeof(int))] = {0};
    struct iovec io[2] = {{&q, sizeof q}, {text, len}};
    struct msghdr m = {.msg_iov = io, .msg_iovlen = 2, .msg_control = control,
                       .msg_controllen = sizeof control};
    struct cmsghdr *c = CMSG_FIRSTHDR(&m);
    c->cmsg_level = SOL_SOCKET;
    c->cmsg_type = SCM_RIGHTS;
    c->cmsg_len = CMSG_LEN(sizeof(int));
    memcpy(CMSG_DATA(c), &out, sizeof out);
    return sendmsg(sockets[slot_used], &m, MSG_NOSIGNAL) < 0 ? -1 : sockets[slot_used];
}

/* Asks the keeper to end the run going on, and every process of its user. */
void contain_kill(void)
{
    Request q = {ASK_KILL, 0, 0, 0, (long)getpid(), 0};
    send(sockets[slot_used], &q, sizeof q, MSG_NOSIGNAL);
}

/* Tells whether the keeper's answer on the run asked for has come; an answer to another
 * asker's run is taken off and passed. */
bool contain_answered(void)
{
    Answer a;
    for (;;) {
        ssize_t n = recv(sockets[slot_used], &a, sizeof a, MSG_PEEK | MSG_DONTWAIT);
        if (n != (ssize_t)sizeof a || a.asker == (long)getpid())
            return n == (ssize_t)sizeof a || (n < 0 && errno != EAGAIN && errno != EINTR) ||
                   n == 0;
        recv(sockets[slot_used], &a, sizeof a, 0);
    }
}

/* Waits for the keeper's answer on the run asked for: how it ended (RUN_EXITED with its wait
 * status, RUN_NOT_RUN with an errno), once every process of its user has ended; exits the
 * grader when the keeper could not end them, or is gone. */
RunEnd contain_wait(int *status)
{
    Answer a;
    ssize_t n;
    /* Answers to another asker's runs (a worker that ended before its answer) are passed. */
    while (((n = recv(sockets[slot_used], &a, sizeof a, 0)) < 0 && errno == EINTR) ||
           (n == (ssize_t)sizeof a && a.asker != (long)getpid()))
        continue;
    if (n != (ssize_t)sizeof a || a.how == RUN_INTERRUPTED) {
        grade_fail(n != (ssize_t)sizeof a ? "the part of the grader that runs students' programs "
                                            "has ended"
                                          : "the processes of a student's program would not end");
        _exit(2);
    }
    *status = a.status;
    return (RunEnd)a.how;
}

/* Makes the folder at path, the grader's, one that this job's student's user may write in
 * (a build's, a program's images and scratch folders): with --run-as, the keeper gives it
 * to that user and the grader's group (keeper_share); false (errno set) when it could not. */
bool contain_share(const char *path)
{
    if (!contain_active())
        return true;
    Request q = {ASK_SHARE, 0, 0, 0, (long)getpid(), 0};
    struct iovec io[2] = {{&q, sizeof q}, {(char *)path, strlen(path) + 1}};
    struct msghdr m = {.msg_iov = io, .msg_iovlen = 2};
    int status = errno = EIO;
    if (sendmsg(sockets[slot_used], &m, MSG_NOSIGNAL) < 0 || contain_wait(&status) != RUN_EXITED)
        return false;
    errno = status;
    return status == 0;
}
