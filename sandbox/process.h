/* process.h: the processes that run, as /proc tells them: each one's parent and user, and a handle to signal it by. */
#ifndef RAYTRA_PROCESS_H
#define RAYTRA_PROCESS_H

#include <stdbool.h>
#include <stddef.h>
#include <sys/types.h>

/* A process: its ids, and a pidfd opened before they were read, or -1. */
typedef struct {
    pid_t pid, parent;
    uid_t uid; /* its real user */
    bool zombie; /* it has ended, and waits to be reaped */
    int pidfd;
    bool marked; /* a mark of the caller's own */
} Process;

size_t process_list(Process **list, size_t *room, uid_t of);

#endif
