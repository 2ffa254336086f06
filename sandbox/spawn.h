/* spawn.h: a child started contained (a student's in the sandbox), watched under its limits, and ended with all it left. */
#ifndef RAYTRA_SPAWN_H
#define RAYTRA_SPAWN_H

#include <stdbool.h>
#include <sys/types.h>

#include "cgroup.h"
#include "sandbox.h"

/* A child on its way: what it execs, and how its end is known. */
typedef struct {
    char **argv;     /* what it execs: the program's words, or bubblewrap's around them */
    bool wrapped;    /* in bubblewrap, which tells a signal N by exiting with 128 + N */
    pid_t pid;       /* this process's child, or 0 when the keeper started it (--run-as) */
    int keeper;      /* the pipe on which the keeper answers, or -1 */
    RunCgroup group; /* its cgroup v2, where it has one of this process's making */
} Spawn;

bool spawn_start(Spawn *s, char *const argv[], const char *dir, int out, double time_limit,
                 long long memory_limit, const SandboxView *view);
bool spawn_ended(const Spawn *s);
bool spawn_end(Spawn *s, bool stop, int *status);
RunResult spawn_run(char *const argv[], const char *dir, double time_limit,
                    long long memory_limit, const SandboxView *view, bool (*stopped)(void));

#endif
