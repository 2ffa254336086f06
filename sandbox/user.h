/* user.h: a student's user (--run-as): found, become, its processes counted, limited and swept. */
#ifndef RAYTRA_USER_H
#define RAYTRA_USER_H

#include <stdbool.h>
#include <sys/types.h>

/* A user: its ids. */
typedef struct {
    uid_t uid;
    gid_t gid;
} User;

/* Seconds the keeper tries to end a student's processes before it calls them unkillable. */
#define SWEEP_GIVE_UP 30

bool user_find(const char *text, User *u);
bool user_become(User u);
int user_processes(uid_t uid, bool end);
void user_limit_processes(void);
bool user_sweep(User u);

#endif
