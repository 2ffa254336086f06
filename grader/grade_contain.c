/* grade_contain.c: students' runs as users of their own (--run-as), and ending every process a run leaves. */
#define _GNU_SOURCE /* setgroups, ppoll */
#include "grade.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <pwd.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include "progress.h"

/* The processes a student's user may have at once: make, a compiler's few, a program's; a
 * fork loop stops there. */
#define STUDENT_PROCESSES 256

/* The most students' users, one a job (--jobs takes at most 64). */
#define MAX_SLOTS 64

/* Seconds the keeper tries to end a student's processes before it calls them unkillable. */
#define SWEEP_GIVE_UP 30

/* A request to the keeper, and its answer. */
enum { ASK_RUN = 1, ASK_KILL = 2, ASK_SHARE = 3 };
typedef struct {
    int ask, argc;
    long long memory_limit;
    double time_limit;
    long asker, serial; /* the asking process and its count of runs, which the answer names */
} Request;
typedef struct {
    int how; /* RUN_EXITED: status is a wait status; RUN_NOT_RUN: an errno; else not contained */
    int status;
    long asker, serial;
} Answer;

/* A user: its ids. */
typedef struct {
    uid_t uid;
    gid_t gid;
} User;

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
    bool swept_once;      /* the last sweep, after the grader ended, was started */
    bool unkillable;      /* a sweep gave up */
} Slot;

/* The grader's side: the sockets to the keeper, one a student's user, and which this
 * process uses (a worker its job's); count 0 when programs run as the grader's own user. */
static int slot_count, slot_used, sockets[MAX_SLOTS];
static pid_t forward_to;
static User grader; /* the grader's user, whose folders the keeper gives to students' users */

/* Reads a user as "NAME", "UID" or "UID:GID"; false (reported) when there is none. */
static bool user_find(const char *text, User *u)
{
    char *end;
    unsigned long id = strtoul(text, &end, 10);
    if (end != text && (*end == '\0' || *end == ':')) {
        unsigned long gid = *end == ':' ? strtoul(end + 1, &end, 10) : id;
        u->uid = (uid_t)id;
        u->gid = (gid_t)gid;
        return *end == '\0' || grade_fail("'%s' is no user: NAME, UID or UID:GID", text);
    }
    struct passwd *pw = getpwnam(text);
    if (pw == NULL)
        return grade_fail("there is no user '%s' (grader/gradescope/setup.sh makes raytra-student "
                          "and raytra-grader)",
                          text);
    *u = (User){pw->pw_uid, pw->pw_gid};
    return true;
}

/* Becomes user u for good: its group alone, real, effective and saved ids, and no way back
 * through a set-user-ID program; false when the system refuses. */
static bool become(User u)
{
    return setgroups(0, NULL) == 0 && setgid(u.gid) == 0 && setuid(u.uid) == 0 &&
           prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) == 0;
}

/* Counts the live processes whose real user is uid (zombies, which have ended, are not);
 * with `end`, stops each (it makes no child once stopped) and kills it, through a pidfd
 * opened before its user is read, so that a pid freed and taken by another process in
 * between is never hit. */
static int processes_of(uid_t uid, bool end)
{
    int count = 0;
    char path[64], line[256];
    DIR *d = opendir("/proc");
    for (struct dirent *e; d != NULL && (e = readdir(d)) != NULL;) {
        if (e->d_name[0] < '0' || e->d_name[0] > '9')
            continue;
        snprintf(path, sizeof path, "/proc/%.20s/status", e->d_name);
        int pidfd = end ? (int)syscall(SYS_pidfd_open, atoi(e->d_name), 0) : -1;
        FILE *f = fopen(path, "r");
        char state = 'X';
        long real = -1;
        while (f != NULL && fgets(line, sizeof line, f) != NULL)
            if (sscanf(line, "State: %c", &state) != 1 && sscanf(line, "Uid: %ld", &real) == 1)
                break;
        if (f != NULL)
            fclose(f);
        bool live = real == (long)uid && state != 'Z' && state != 'X';
        count += live;
        for (int k = 0; k < 2 && pidfd >= 0 && live; k++)
            syscall(SYS_pidfd_send_signal, pidfd, k == 0 ? SIGSTOP : SIGKILL, NULL, 0);
        if (pidfd >= 0)
            close(pidfd);
    }
    if (d != NULL)
        closedir(d);
    return count;
}

/* Sets the limit on the processes of the child's user: what it has now and STUDENT_PROCESSES
 * more (root's own are not limited). */
void contain_limit_processes(void)
{
    if (getuid() == 0)
        return;
    rlim_t n = (rlim_t)processes_of(getuid(), false) + STUDENT_PROCESSES;
    setrlimit(RLIMIT_NPROC, &(struct rlimit){n, n});
}

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

/* In the keeper: starts a process that ends every process of the slot's user until none
 * lives, as root, which no student's process may signal or stop, then has the user's IPC
 * objects removed; it exits 0, or 1 after SWEEP_GIVE_UP seconds. */
static void sweep_start(Slot *s)
{
    s->sweeper = fork();
    if (s->sweeper != 0)
        return;
    signal(SIGINT, SIG_DFL);
    signal(SIGTERM, SIG_DFL);
    signal(SIGHUP, SIG_DFL);
    /* First at once, as the user, whose kill(-1) reaches all its processes in one call;
     * then by name, as root, should a process of theirs have stopped that one. */
    pid_t at_once = fork();
    if (at_once == 0) {
        if (become(s->user))
            kill(-1, SIGKILL);
        _exit(0);
    }
    double give_up = clock_now() + SWEEP_GIVE_UP;
    for (int k = 0; processes_of(s->user.uid, true) > 0; k++) {
        if (clock_now() > give_up)
            _exit(1);
        usleep(k < 100 ? 100 : 1000);
    }
    /* It has ended (a process of the user, it was ended too): its kill(-1) is not late. */
    if (at_once > 0)
        waitpid(at_once, NULL, 0);
    /* The user's System V IPC objects outlive its processes: with none left, it removes them
     * (in namespaces, the IPC namespace's end does it). */
    pid_t ipcrm = fork();
    if (ipcrm == 0) {
        int null = open("/dev/null", O_WRONLY);
        if (become(s->user) && null >= 0 && dup2(null, 1) >= 0 && dup2(null, 2) >= 0)
            execlp("ipcrm", "ipcrm", "--all", (char *)NULL);
        _exit(RUN_EXEC_FAILED);
    }
    if (ipcrm > 0)
        waitpid(ipcrm, NULL, 0);
    _exit(0);
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
    if (err == 0 && (s->child = fork()) == 0) {
        signal(SIGINT, SIG_DFL);
        signal(SIGTERM, SIG_DFL);
        signal(SIGHUP, SIG_DFL);
        if (!become(s->user))
            _exit(RUN_EXEC_FAILED);
        run_child_setup(dir[0] != '\0' ? dir : NULL, out, q->memory_limit, q->time_limit, true);
        execvp(argv[0], argv);
        grade_fail("cannot run '%s': %s", argv[0], strerror(errno));
        _exit(RUN_EXEC_FAILED);
    }
    err = err != 0 ? err : s->child < 0 ? errno : 0;
    free(argv);
    s->asked = *q;
    if (err != 0) {
        s->child = 0;
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
 * and exits as the grader did. It reads nothing but the requests on its sockets. */
static void keeper_main(Slot *slots)
{
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

/* With --run-as (as root): checks the users, then splits the grader in two. The parent,
 * root, becomes the keeper (keeper_main) and never returns; the child becomes the grader's
 * user for good and returns true, to grade; students' builds and programs (run_student)
 * run as the users of run_as, one a job, started and ended by the keeper. Without run_as,
 * returns true and they run as the grader's user, its subreaper's sweep ending them.
 * False (reported) on trouble. */
bool contain_start(const char *run_as, const char *grader_user, int jobs)
{
    static Slot slots[MAX_SLOTS];
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
        if (!user_find(name, &slots[slot_count].user))
            return false;
        User u = slots[slot_count++].user;
        if (u.uid == 0 || u.uid == grader.uid)
            return grade_fail("--run-as %s: a student's user must be neither root nor the "
                              "grader's user",
                              name);
        for (int k = 0; k + 1 < slot_count; k++)
            if (slots[k].user.uid == u.uid)
                return grade_fail("--run-as names the user %s twice", name);
        if (processes_of(u.uid, false) > 0)
            return grade_fail("the user %s has processes running: --run-as needs users that "
                              "run nothing else, since every process of theirs is ended",
                              name);
    }
    if (slot_count < jobs)
        return grade_fail("--jobs %d needs %d users in --run-as, one a job (it names %d)", jobs,
                          jobs, slot_count);
    int pair[MAX_SLOTS][2];
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
        slots[k].socket = pair[k][0];
    }
    if (child > 0) {
        forward_to = child;
        keeper_main(slots);
    }
    /* PR_SET_PDEATHSIG after the ids change, which clears it: the grader ends with the keeper. */
    if (!become(grader) || prctl(PR_SET_PDEATHSIG, SIGKILL, 0, 0, 0) != 0 ||
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

/* Has each student's user make what it left in folder (a work folder of an earlier run)
 * writable by all, for the grader to remove it, the submissions' folders, closed once
 * graded, opened to them first; nothing without --run-as. */
void contain_release(const char *folder)
{
    int count = 0;
    char **names = slot_count > 0 ? path_list_folders(folder, &count) : NULL;
    for (int k = 0; k < count; k++)
        chmod(grade_format("%s/%s", folder, names[k]), 0711);
    char *chmod[] = {"chmod", "-R", "a+rwX", "--", (char *)folder, NULL};
    for (int k = 0; k < slot_count; k++) {
        contain_use_slot(k);
        run_student(chmod, NULL, NULL, 600, 0, &(View){{folder, NULL}, NULL, 0});
    }
    contain_use_slot(0);
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
