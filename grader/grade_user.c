/* grade_user.c: a student's user of its own (--run-as): found, become, its processes counted, limited and swept. */
#define _GNU_SOURCE /* setgroups */
#include "grade_user.h"

#include <dirent.h>
#include <fcntl.h>
#include <grp.h>
#include <pwd.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include "grade_base.h"
#include "grading.h"
#include "progress.h"

/* The processes a student's user may have at once: make, a compiler's few, a program's; a
 * fork loop stops there. */
#define STUDENT_PROCESSES 256

/* Reads a user as "NAME", "UID" or "UID:GID"; false (reported) when there is none. */
bool user_find(const char *text, User *u)
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
        return grade_fail("there is no user '%s' (platforms/gradescope/setup.sh makes raytra-student "
                          "and raytra-grader)",
                          text);
    *u = (User){pw->pw_uid, pw->pw_gid};
    return true;
}

/* Becomes user u for good: its group alone, real, effective and saved ids, and no way back
 * through a set-user-ID program; false when the system refuses. */
bool user_become(User u)
{
    return setgroups(0, NULL) == 0 && setgid(u.gid) == 0 && setuid(u.uid) == 0 &&
           prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) == 0;
}

/* Counts the live processes whose real user is uid (zombies, which have ended, are not);
 * with `end`, stops each (it makes no child once stopped) and kills it, through a pidfd
 * opened before its user is read, so that a pid freed and taken by another process in
 * between is never hit. */
int user_processes(uid_t uid, bool end)
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
void user_limit_processes(void)
{
    if (getuid() == 0)
        return;
    rlim_t n = (rlim_t)user_processes(getuid(), false) + STUDENT_PROCESSES;
    setrlimit(RLIMIT_NPROC, &(struct rlimit){n, n});
}

/* In the keeper: starts a process that ends every process of user u until none lives, as
 * root, which no student's process may signal or stop, then has the user's IPC objects
 * removed; it exits 0, or 1 after SWEEP_GIVE_UP seconds. Returns its pid (-1: none). */
pid_t user_sweep(User u)
{
    pid_t sweeper = fork();
    if (sweeper != 0)
        return sweeper;
    signal(SIGINT, SIG_DFL);
    signal(SIGTERM, SIG_DFL);
    signal(SIGHUP, SIG_DFL);
    /* First at once, as the user, whose kill(-1) reaches all its processes in one call;
     * then by name, as root, should a process of theirs have stopped that one. */
    pid_t at_once = fork();
    if (at_once == 0) {
        if (user_become(u))
            kill(-1, SIGKILL);
        _exit(0);
    }
    double give_up = clock_now() + SWEEP_GIVE_UP;
    for (int k = 0; user_processes(u.uid, true) > 0; k++) {
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
        if (user_become(u) && null >= 0 && dup2(null, 1) >= 0 && dup2(null, 2) >= 0)
            execlp("ipcrm", "ipcrm", "--all", (char *)NULL);
        _exit(RUN_EXEC_FAILED);
    }
    if (ipcrm > 0)
        waitpid(ipcrm, NULL, 0);
    _exit(0);
}
