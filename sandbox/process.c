/* process.c: the processes that run, as /proc tells them: each one's parent and user, and a handle to signal it by. */
#define _GNU_SOURCE /* syscall */
#include "process.h"

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/syscall.h>
#include <unistd.h>

/* Lists every process into *list (of *room, grown as it needs); returns how many. Those of
 * the user `of` keep a pidfd opened before their parent and user were read, so that a pid
 * freed and taken by another process in between is never signalled (the caller closes
 * them); the others have none. */
size_t process_list(Process **list, size_t *room, uid_t of)
{
    size_t n = 0;
    char path[64], line[256];
    DIR *d = opendir("/proc");
    for (struct dirent *e; d != NULL && (e = readdir(d)) != NULL;) {
        if (e->d_name[0] < '0' || e->d_name[0] > '9')
            continue;
        size_t more = n < *room ? *room : *room * 2 + 256;
        Process *grown = more == *room ? *list : realloc(*list, more * sizeof **list);
        if (grown == NULL)
            break;
        *list = grown;
        *room = more;
        pid_t pid = (pid_t)atol(e->d_name);
        int pidfd = of != (uid_t)-1 ? (int)syscall(SYS_pidfd_open, pid, 0) : -1;
        snprintf(path, sizeof path, "/proc/%.20s/status", e->d_name);
        FILE *f = fopen(path, "r");
        char state = 'X';
        long parent = -1, uid = -1;
        /* "State:" and "PPid:" come before "Uid:", the last line read. */
        while (f != NULL && fgets(line, sizeof line, f) != NULL &&
               sscanf(line, "Uid: %ld", &uid) != 1)
            if (sscanf(line, "State: %c", &state) != 1)
                sscanf(line, "PPid: %ld", &parent);
        if (f != NULL)
            fclose(f);
        if (pidfd >= 0 && (uid_t)uid != of)
            close(pidfd);
        if (uid >= 0 && state != 'X')
            (*list)[n++] = (Process){pid, (pid_t)parent, (uid_t)uid, state == 'Z',
                                     (uid_t)uid == of ? pidfd : -1, false};
    }
    if (d != NULL)
        closedir(d);
    return n;
}
