/* grade_keeper.c: root's part with --run-as, the keeper: each run started as a student's user, and ended. */
#define _GNU_SOURCE /* ppoll */
#include "grade_keeper.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "grade_base.h"
#include "grade_cgroup.h"
#include "grade_child.h"
#include "grading.h"

/* What the keeper knows of one student's user: the socket of the grader (or worker) that
 * asks for runs as it, the run going on, and the sweep ending what the run left. */
typedef struct {
    User user;
    int socket;           /* -1 once the grader closed it */
    pid_t child, sweeper; /* 0: none */
    int status;           /* the child's wait status, once reaped */
    bool answer_due;      /* a run was asked for and not yet answered */
    Request asked;        /* that run's request */
    Request next;         /* a run asked for while one went on (its asker ended): or ask 0 */
    char *next_text;      /* its words, and its output's descriptor */
    size_t next_len;
    int next_out;
    RunCgroup cgroup;     /* the run's cgroup v2, where there is one */
    bool swept_once;      /* the last sweep, after the grader ended, was started */
    bool unkillable;      /* a sweep gave up */
} Slot;

/* The keeper's slots in use, the grader it serves, and the grader's user, whose folders the
 * keeper gives to students' users. */
static int slot_count;
static pid_t forward_to;
static User grader;

/* The keeper's signal handler: a stop asked of the keeper is passed on to the grader. */
static void forward(int sig)
{
    if (forward_to > 0)
        kill(forward_to, sig);
}

/* The keeper's handler of SIGCHLD, which only wakes ppoll. */
static void wake(int sig)
{
    (void)sig;
}

/* In the keeper: ends the run's cgroup, where it has one (every process at once), and starts
 * the sweep that ends every process of the slot's user (user_sweep). */
static void sweep_start(Slot *s)
{
    cgroup_run_kill(s->cgroup);
    s->sweeper = user_sweep(s->user);
}

/* In the keeper: starts the run a request asks for (argv, in dir, output to out) as the
 * slot's user, in a new process group, under the limits; answers at once when it cannot. */
static void keeper_spawn(Slot *s, const Request *q, char *text, size_t len, int out)
{
    char **argv = calloc((size_t)q->argc + 1, sizeof *argv), *dir = text;
    char *p = text + strnlen(text, len) + 1;
    for (int k = 0; argv != NULL && k < q->argc && p < text + len; k++, p += strlen(p) + 1)
        argv[k] = p;
    int err = argv == NULL || p > text + len || argv[q->argc - 1] == NULL ? EINVAL : 0;
    if (err == 0)
        s->cgroup = cgroup_run_open(q->memory_limit);
    if (err == 0 && (s->child = fork()) == 0) {
        signal(SIGINT, SIG_DFL);
        signal(SIGTERM, SIG_DFL);
        signal(SIGHUP, SIG_DFL);
        cgroup_enter(s->cgroup);
        if (!user_become(s->user))
            _exit(RUN_EXEC_FAILED);
        child_setup(dir[0] != '\0' ? dir : NULL, out, q->memory_limit, q->time_limit, true);
        execvp(argv[0], argv);
        grade_fail("cannot run '%s': %s", argv[0], strerror(errno));
        _exit(RUN_EXEC_FAILED);
    }
    err = err != 0 ? err : s->child < 0 ? errno : 0;
    free(argv);
    s->asked = *q;
    if (err != 0) {
        s->child = 0;
        cgroup_run_end(&s->cgroup);
        Answer a = {RUN_NOT_RUN, err, q->asker, q->serial};
        send(s->socket, &a, sizeof a, MSG_NOSIGNAL);
        return;
    }
    s->answer_due = true;
}

/* In the keeper: gives the folder at path, one of the grader's, to the slot's user and the
 * grader's group, mode 2770: the student writes in it, the grader reads it, no classmate
 * enters it (grade_submission.c closes it to all once graded); returns 0 or an errno. */
static int keeper_share(const Slot *s, const char *path)
{
    int fd = open(path, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    struct stat st;
    int err = fd < 0 || fstat(fd, &st) != 0 ? errno
              : st.st_uid != grader.uid    ? EPERM
              : fchown(fd, s->user.uid, grader.gid) != 0 || fchmod(fd, 02770) != 0 ? errno
                                                                                      : 0;
    if (fd >= 0)
        close(fd);
    return err;
}

/* In the keeper: reads the request waiting on slot s's socket and does it; a socket closed
 * (the grader or its worker ended) has what runs as the slot's user ended. */
static void keeper_read(Slot *s)
{
    static char text[1 << 16];
    Request q = {0};
    char control[CMSG_SPACE(sizeof(int))];
    struct iovec io[2] = {{&q, sizeof q}, {text, sizeof text - 1}};
    struct msghdr m = {.msg_iov = io, .msg_iovlen = 2, .msg_control = control,
                       .msg_controllen = sizeof control};
    ssize_t n = recvmsg(s->socket, &m, MSG_CMSG_CLOEXEC);
    if (n < 0 && errno == EINTR)
        return;
    int out = -1;
    struct cmsghdr *c = n > 0 ? CMSG_FIRSTHDR(&m) : NULL;
    if (c != NULL && c->cmsg_type == SCM_RIGHTS)
        memcpy(&out, CMSG_DATA(c), sizeof out);
    if (n <= 0) {
        close(s->socket);
        s->socket = -1;
        if (s->child > 0 && s->sweeper == 0)
            sweep_start(s);
    } else if (q.ask == ASK_RUN && out >= 0 && q.argc > 0 && (size_t)n > sizeof q) {
        text[n - sizeof q] = '\0';
        if (s->child == 0 && !s->answer_due) {
            keeper_spawn(s, &q, text, (size_t)n - sizeof q, out);
        } else {
            /* A run asked for while another goes on: the other's asker (a worker) ended
             * without waiting for it. It is ended, and this one starts after the sweep. */
            if (s->next.ask != 0)
                close(s->next_out);
            free(s->next_text);
            s->next = q;
            s->next_len = (size_t)n - sizeof q;
            s->next_text = malloc(s->next_len + 1);
            s->next.ask = s->next_text != NULL ? ASK_RUN : 0;
            if (s->next_text != NULL)
                memcpy(s->next_text, text, s->next_len + 1);
            s->next_out = s->next_text != NULL ? dup(out) : -1;
            if (s->child > 0 && s->sweeper == 0)
                sweep_start(s);
        }
    } else if (q.ask == ASK_KILL && s->child > 0 && s->sweeper == 0) {
        sweep_start(s);
    } else if (q.ask == ASK_SHARE && (size_t)n > sizeof q) {
        text[n - sizeof q] = '\0';
        Answer a = {RUN_EXITED, keeper_share(s, text), q.asker, q.serial};
        send(s->socket, &a, sizeof a, MSG_NOSIGNAL);
    }
    if (out >= 0)
        close(out);
}

/* In the keeper: takes note that process p ended with status st: the grader, a run (whose
 * user's processes are then swept), a sweep (whose run is then answered), or an orphan. */
static bool keeper_reaped(Slot *slots, pid_t p, int st)
{
    for (int k = 0; k < slot_count; k++) {
        Slot *s = &slots[k];
        if (p == s->child) {
            s->child = -1; /* reaped, not yet answered */
            s->status = st;
            if (s->sweeper == 0)
                sweep_start(s);
        } else if (p == s->sweeper) {
            s->sweeper = 0;
            cgroup_run_end(&s->cgroup);
            s->unkillable |= !WIFEXITED(st) || WEXITSTATUS(st) != 0;
        }
        if (s->child == -1 && s->sweeper == 0 && s->answer_due) {
            Answer a = {s->unkillable ? RUN_INTERRUPTED : RUN_EXITED, s->status, s->asked.asker,
                        s->asked.serial};
            if (s->socket >= 0)
                send(s->socket, &a, sizeof a, MSG_NOSIGNAL);
            s->answer_due = false;
            s->child = 0;
        }
        if (s->child == 0 && !s->answer_due && s->next.ask != 0) {
            s->next.ask = 0;
            keeper_spawn(s, &s->next, s->next_text, s->next_len, s->next_out);
            close(s->next_out);
        }
    }
    return p == forward_to;
}

/* The keeper: root's part, which only starts runs as the students' users and ends them, for
 * the grader, its child, until the grader has ended; then ends whatever of theirs is left
 * and exits as the grader did. It reads nothing but the requests on its sockets: users[k]'s
 * on sockets[k], of `count`; grader_pid is the grader's, grader_user its user. */
void keeper_main(const User *users, const int *sockets, int count, User grader_user,
                 pid_t grader_pid)
{
    static Slot slots[MAX_SLOTS];
    for (int k = 0; k < count; k++)
        slots[k] = (Slot){.user = users[k], .socket = sockets[k], .cgroup = {-1, ""}};
    slot_count = count;
    grader = grader_user;
    forward_to = grader_pid;
    prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0);
    struct sigaction pass = {.sa_handler = forward}, wakeup = {.sa_handler = wake};
    sigaction(SIGINT, &pass, NULL);
    sigaction(SIGTERM, &pass, NULL);
    sigaction(SIGHUP, &pass, NULL);
    sigaction(SIGCHLD, &wakeup, NULL);
    sigset_t blocked, open;
    sigemptyset(&blocked);
    sigaddset(&blocked, SIGCHLD);
    sigprocmask(SIG_BLOCK, &blocked, &open);
    sigdelset(&open, SIGCHLD);
    int grader_status = 0;
    bool grader_ended = false;
    for (;;) {
        int st;
        for (pid_t p; (p = waitpid(-1, &st, WNOHANG)) > 0;)
            if (keeper_reaped(slots, p, st)) {
                grader_ended = true;
                grader_status = st;
            }
        bool busy = false;
        for (int k = 0; k < slot_count; k++) {
            Slot *s = &slots[k];
            if (grader_ended && s->child == 0 && s->sweeper == 0 && !s->swept_once) {
                s->swept_once = true;
                sweep_start(s);
            }
            busy |= s->child != 0 || s->sweeper != 0 || !s->swept_once;
        }
        if (grader_ended && !busy)
            break;
        struct pollfd fds[MAX_SLOTS];
        for (int k = 0; k < slot_count; k++)
            fds[k] = (struct pollfd){.fd = slots[k].socket, .events = POLLIN};
        if (ppoll(fds, (nfds_t)slot_count, NULL, &open) > 0)
            for (int k = 0; k < slot_count; k++)
                if (fds[k].revents != 0)
                    keeper_read(&slots[k]);
    }
    cgroup_finish();
    bool unkillable = false;
    for (int k = 0; k < slot_count; k++)
        unkillable |= slots[k].unkillable;
    if (unkillable)
        grade_fail("some processes of a student's user would not end within %d s", SWEEP_GIVE_UP);
    if (WIFSIGNALED(grader_status)) {
        signal(WTERMSIG(grader_status), SIG_DFL);
        raise(WTERMSIG(grader_status));
    }
    _exit(unkillable ? 2 : WEXITSTATUS(grader_status));
}
