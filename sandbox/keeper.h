/* keeper.h: root's part with --run-as, the keeper, and the requests it answers. */
#ifndef RAYTRA_KEEPER_H
#define RAYTRA_KEEPER_H

#include <sys/types.h>

#include "user.h"

/* The most students' users, one a job (--jobs takes at most 64). */
#define MAX_SLOTS 64

/* A request to the keeper (with, but for a kill, the pipe of its answer), and its answer. */
enum { ASK_RUN = 1, ASK_KILL = 2, ASK_SHARE = 3 };
enum { ANSWER_EXITED, ANSWER_NOT_RUN, ANSWER_UNKILLABLE };
typedef struct {
    int ask, argc;
    long long memory_limit;
    double time_limit;
} Request;
typedef struct {
    int how; /* ANSWER_EXITED: status is a wait status; ANSWER_NOT_RUN: an errno */
    int status;
} Answer;

void keeper_main(const User *users, const int *sockets, int count, User grader_user,
                 pid_t grader_pid);

#endif
