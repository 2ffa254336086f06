/* user.c: a student's user of its own (--run-as): found, become, its processes counted, limited and swept. */
#define _GNU_SOURCE /* setgroups, syscall */
#include "user.h"

#include <fcntl.h>
#include <grp.h>
#include <pwd.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "process.h"
#include "sandbox.h"

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
        return *end == '\0' || sandbox_fail("'%s' is no user: NAME, UID or UID:GID", text);
    }
    struct passwd *pw = getpwnam(text);
    if (pw == NULL)
        return sandbox_fail("there is no user '%s' (platforms/gradescope/setup.sh makes "
                            "raytra-student and raytra-grader)",
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
 * with `end`, stops each (it makes no child once stopped) and kills it, through its pidfd. */
int user_processes(uid_t uid, bool end)
{
    static Process *list;
    static size_t room;
    size_t n = process_list(&list, &room, end ? uid : (uid_t)-1);
    int count = 0;
    for (size_t k = 0; k < n; k++) {
        bool live = list[k].uid == uid && !list[k].zombie;
        count += live;
        for (int s = 0; s < 2 && live && list[k].pidfd >= 0; s++)
            syscall(SYS_pidfd_send_signal, list[k].pidfd, s == 0 ? SIGSTOP : SIGKILL, NULL, 0);
        if (list[k].pidfd >= 0)
            close(list[k].pidfd);
    }
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

/* Starts a process as user u, its output thrown away, that runs argv, or with NULL kills
 * every process of u (kill(-1) as u reaches them all in one call); returns its pid. */
static pid_t as_user(User u, char *const argv[])
{
    pid_t p = fork();
    int null = p == 0 ? open("/dev/null", O_WRONLY) : -1;
    if (p == 0 && user_become(u) && null >= 0 && dup2(null, 1) >= 0 && dup2(null, 2) >= 0) {
        if (argv != NULL)
            execvp(argv[0], argv);
        else
            kill(-1, SIGKILL);
    }
    if (p == 0)
        _exit(SANDBOX_EXEC_FAILED);
    return p;
}

/* In the keeper, as root, which no student's process may signal or stop: ends every process
 * of user u until none lives, then has the user's IPC objects removed; false when some still
 * lived after SWEEP_GIVE_UP seconds. */
bool user_sweep(User u)
{
    /* First at once, as the user; then one by one, as root, should a process of theirs have
     * stopped that one before its kill(-1). */
    pid_t at_once = as_user(u, NULL);
    time_t give_up = time(NULL) + SWEEP_GIVE_UP;
    for (int k = 0; user_processes(u.uid, true) > 0; k++) {
        if (time(NULL) > give_up)
            return false;
        usleep(k < 100 ? 100 : 1000);
    }
    /* It has ended (a process of the user, it was ended too): its kill(-1) is not late. */
    waitpid(at_once, NULL, 0);
    /* The user's System V IPC objects outlive its processes: with none left, it removes them
     * (in namespaces, the IPC namespace's end does it). */
    waitpid(as_user(u, (char *[]){"ipcrm", "--all", NULL}), NULL, 0);
    return true;
}
