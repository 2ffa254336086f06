/* cgroup.c: a cgroup v2 a student's run, where the grader may make them: limits on the whole run, and its end in one write. */
#define _GNU_SOURCE /* O_DIRECTORY, usleep */
#include "cgroup.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "sandbox.h"

/* The processes a run may have at once in its cgroup: make, a compiler's few, a program's. */
#define CGROUP_PROCESSES 256

/* Seconds a killed cgroup is given to empty before it is left behind. */
#define CGROUP_EMPTY_WAIT 10

/* The grader's cgroup, every run's below it (an fd, -1 when there is none), and whether the
 * controllers of memory and processes are enabled below it. */
static int grader_dir = -1;
static char grader_path[512];
static pid_t maker; /* the process that made it, which alone removes it */
static bool limits_memory, limits_processes;

/* Writes text to the file name in the folder dir; false when it cannot. */
static bool put(int dir, const char *name, const char *text)
{
    int fd = openat(dir, name, O_WRONLY | O_CLOEXEC);
    bool ok = fd >= 0 && write(fd, text, strlen(text)) == (ssize_t)strlen(text);
    if (fd >= 0)
        close(fd);
    return ok;
}

/* Tells whether the cgroup at dir holds no process (its cgroup.events says "populated 0"). */
static bool empty(int dir)
{
    char text[256] = "";
    int fd = openat(dir, "cgroup.events", O_RDONLY | O_CLOEXEC);
    ssize_t n = fd >= 0 ? read(fd, text, sizeof text - 1) : -1;
    if (fd >= 0)
        close(fd);
    text[n > 0 ? n : 0] = '\0';
    return strstr(text, "populated 0") != NULL;
}

/* Finds where the cgroup v2 hierarchy is mounted (/sys/fs/cgroup, or its unified/ on a
 * system that mounts v1 beside it), in /proc/self/mountinfo; false when it is not. */
static bool find_mount(char *path, size_t size)
{
    FILE *f = fopen("/proc/self/mountinfo", "r");
    char line[1024], point[512];
    bool found = false;
    /* "ID PARENT MAJ:MIN ROOT POINT OPTIONS... - TYPE SOURCE SUPER": TYPE cgroup2. */
    while (!found && f != NULL && fgets(line, sizeof line, f) != NULL)
        found = strstr(line, " - cgroup2 ") != NULL &&
                sscanf(line, "%*s %*s %*s %*s %511s", point) == 1;
    if (f != NULL)
        fclose(f);
    return found && snprintf(path, size, "%s", point) < (int)size;
}

/* Makes the grader's cgroup, where the system lets it (as root, on a cgroup v2 hierarchy),
 * and enables below it what it can of the memory and pids controllers; false, with every
 * run limited by rlimits alone, when it cannot. */
bool cgroup_start(void)
{
    char mount[256];
    if (geteuid() != 0 || !find_mount(mount, sizeof mount))
        return false;
    snprintf(grader_path, sizeof grader_path, "%s/raytra-grade-%ld", mount, (long)getpid());
    if (mkdir(grader_path, 0755) != 0)
        return false;
    grader_dir = open(grader_path, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    maker = getpid();
    /* Each controller alone, so that one the system lacks leaves the other on. */
    limits_memory = grader_dir >= 0 && put(grader_dir, "cgroup.subtree_control", "+memory");
    limits_processes = grader_dir >= 0 && put(grader_dir, "cgroup.subtree_control", "+pids");
    return grader_dir >= 0;
}

/* Says what the cgroups limit, for the grader's line on its sandbox: "" when there are none. */
const char *cgroup_describe(void)
{
    if (grader_dir < 0)
        return "";
    return limits_memory && limits_processes ? "cgroup v2: each run's memory and processes "
                                               "together, and its end"
           : limits_memory    ? "cgroup v2: each run's memory together, and its end"
           : limits_processes ? "cgroup v2: each run's processes together, and its end"
                              : "cgroup v2: each run's end (no memory or pids controller here)";
}

/* Makes the cgroup of a run about to start, whose processes together use at most
 * memory_limit bytes (0: no limit) and CGROUP_PROCESSES processes; the child enters it with
 * cgroup_enter. Its dir is -1 without the grader's cgroup, or when it cannot be made. */
RunCgroup cgroup_run_open(long long memory_limit)
{
    static long serial;
    RunCgroup g = {-1, ""};
    if (grader_dir < 0)
        return g;
    snprintf(g.name, sizeof g.name, "run-%ld-%ld", (long)getpid(), ++serial);
    if (mkdirat(grader_dir, g.name, 0755) != 0 ||
        (g.dir = openat(grader_dir, g.name, O_RDONLY | O_DIRECTORY | O_CLOEXEC)) < 0)
        return g;
    char text[32];
    snprintf(text, sizeof text, "%lld", memory_limit);
    if (limits_memory && memory_limit > 0) {
        put(g.dir, "memory.max", text);
        put(g.dir, "memory.swap.max", "0");
    }
    snprintf(text, sizeof text, "%d", CGROUP_PROCESSES);
    if (limits_processes)
        put(g.dir, "pids.max", text);
    return g;
}

/* In the run's child, before it becomes a student's user or execs: enters the run's cgroup g,
 * with every process it will make; exits the child when it cannot, rather than run it
 * where its end could miss some of them. */
void cgroup_enter(RunCgroup g)
{
    if (g.dir >= 0 && !put(g.dir, "cgroup.procs", "0"))
        _exit(SANDBOX_EXEC_FAILED);
}

/* Kills every process of the run's cgroup g at once, without waiting (cgroup_run_end waits). */
void cgroup_run_kill(RunCgroup g)
{
    if (g.dir >= 0)
        put(g.dir, "cgroup.kill", "1");
}

/* Ends every process of the run's cgroup g at once (cgroup.kill: a fork that races it
 * loses), waits until none is left, and removes the cgroup; nothing without one. */
void cgroup_run_end(RunCgroup *g)
{
    if (g->dir < 0)
        return;
    cgroup_run_kill(*g);
    for (int k = 0; !empty(g->dir) && k < CGROUP_EMPTY_WAIT * 1000; k++)
        usleep(1000);
    close(g->dir);
    g->dir = -1;
    unlinkat(grader_dir, g->name, AT_REMOVEDIR);
}

/* Removes the grader's cgroup, once every run's is gone, in the process that made it (the
 * keeper with --run-as; its child, the grader, only lets it go). */
void cgroup_finish(void)
{
    if (grader_dir < 0 || getpid() != maker) {
        if (grader_dir >= 0)
            close(grader_dir);
        grader_dir = -1;
        return;
    }
    close(grader_dir);
    grader_dir = -1;
    rmdir(grader_path);
}
