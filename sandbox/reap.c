/* reap.c: ending every process a run left below the grader, to which orphans come back (a subreaper). */
#define _GNU_SOURCE /* usleep */
#include "reap.h"

#include <signal.h>
#include <stdbool.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include "process.h"

/* Ends every process below this one (a subreaper, to which orphans come back) but the
 * children in keep[0..keep_count) and what is below them, and reaps those it ended; returns
 * once none is left. Each round marks this process's other children and, from parent to
 * child, what is below them, and kills all it marked; a child made after the list was read
 * comes back to this process when its parent is killed, and is ended in the next round. */
void reap_strays(const pid_t *keep, int keep_count)
{
    Process *list = NULL;
    size_t room = 0;
    for (int rounds = 0;; rounds++) {
        size_t n = process_list(&list, &room, (uid_t)-1), strays = 0;
        for (size_t k = 0; k < n; k++) {
            list[k].marked = list[k].parent == getpid();
            for (int j = 0; j < keep_count; j++)
                list[k].marked &= list[k].pid != keep[j];
            strays += list[k].marked;
        }
        if (strays == 0)
            break;
        for (bool grew = true; grew;) {
            grew = false;
            for (size_t k = 0; k < n; k++)
                for (size_t j = 0; j < n && !list[k].marked; j++)
                    grew |= list[k].marked = list[j].marked && list[k].parent == list[j].pid;
        }
        for (size_t k = 0; k < n; k++)
            if (list[k].marked)
                kill(list[k].pid, SIGKILL);
        /* The direct ones are reaped when they have ended; the rest come back to be. */
        int reaped = 0;
        for (size_t k = 0; k < n; k++)
            reaped += list[k].marked && list[k].parent == getpid() &&
                      waitpid(list[k].pid, NULL, WNOHANG) > 0;
        if (reaped == 0)
            usleep(rounds < 100 ? 200 : 2000);
    }
    free(list);
}
