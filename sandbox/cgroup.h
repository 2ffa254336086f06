/* cgroup.h: a cgroup v2 a student's run, where the grader may make them (cgroup.c). */
#ifndef RAYTRA_CGROUP_H
#define RAYTRA_CGROUP_H

#include <stdbool.h>

/* One run's cgroup: its folder (an fd, -1 when the run has none) and its name. */
typedef struct {
    int dir;
    char name[48];
} RunCgroup;

bool cgroup_start(void);
const char *cgroup_describe(void);
RunCgroup cgroup_run_open(long long memory_limit);
void cgroup_enter(RunCgroup g);
void cgroup_run_kill(RunCgroup g);
void cgroup_run_end(RunCgroup *g);
void cgroup_finish(void);

#endif
