/* grade_keeper.h: root's part with --run-as, the keeper, and the requests it answers. */
#ifndef RAYTRA_GRADE_KEEPER_H
#define RAYTRA_GRADE_KEEPER_H

#include <sys/types.h>

#include "grade_user.h"

/* The most students' users, one a job (--jobs takes at most 64). */
#define MAX_SLOTS 64

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

void keeper_main(const User *users, const int *sockets, int count, User grader_user,
                 pid_t grader_pid);

#endif
