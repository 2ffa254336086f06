/* grade_reap.c: ending every process a run left below the grader, to which orphans come back (a subreaper). */
#define _GNU_SOURCE /* usleep */
#include "grade_reap.h"

#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

/* Appends to list (of *count, room for *room) the pids in the children files of process p's
 * threads; false when the kernel has no such files. */
static bool children_of(pid_t p, pid_t **list, size_t *count, size_t *room)
{
    char path[64];
    snprintf(path, sizeof path, "/proc/%ld/task", (long)p);
    DIR *tasks = opendir(path);
    bool found = tasks != NULL;
    for (struct dirent *t; tasks != NULL && (t = readdir(tasks)) != NULL;) {
        if (t->d_name[0] == '.')
            continue;
        snprintf(path, sizeof path, "/proc/%ld/task/%.20s/children", (long)p, t->d_name);
        FILE *f = fopen(path, "r");
        found = found && (f != NULL || errno != ENOENT);
        for (long child; f != NULL && fscanf(f, "%ld", &child) == 1;) {
            if (*count == *room) {
                *room = *room * 2 + 64;
                pid_t *grown = realloc(*list, *room * sizeof **list);
                if (grown == NULL)
                    break;
                *list = grown;
            }
            (*list)[(*count)++] = (pid_t)child;
        }
        if (f != NULL)
            fclose(f);
    }
    if (tasks != NULL)
        closedir(tasks);
    return found;
}

/* Appends the pids of this process's children to list as children_of does, found by the
 * parent each process names (/proc/PID/stat) on a kernel without children files. */
static void my_children(pid_t **list, size_t *count, size_t *room)
{
    if (children_of(getpid(), list, count, room))
        return;
    char path[64], text[512];
    DIR *d = opendir("/proc");
    for (struct dirent *e; d != NULL && (e = readdir(d)) != NULL;) {
        snprintf(path, sizeof path, "/proc/%.20s/stat", e->d_name);
        FILE *f = e->d_name[0] >= '0' && e->d_name[0] <= '9' ? fopen(path, "r") : NULL;
        size_t n = f != NULL ? fread(text, 1, sizeof text - 1, f) : 0;
        if (f != NULL)
            fclose(f);
        text[n] = '\0';
        /* "pid (name) state ppid ...": the name may hold spaces and parentheses. */
        const char *name_end = strrchr(text, ')');
        long ppid;
        if (name_end != NULL && sscanf(name_end + 1, " %*c %ld", &ppid) == 1 &&
            ppid == (long)getpid() && *count < *room)
            (*list)[(*count)++] = (pid_t)atol(e->d_name);
    }
    if (d != NULL)
        closedir(d);
}

/* Ends every process below this one (a subreaper, to which orphans come back) but the
 * children in keep[0..keep_count) and what is below them, and reaps those it ended; returns
 * once none is left. Each process is stopped before its children are read, so that it
 * makes no child after and keeps those it has, and all are killed then; a child made while
 * its parent was being stopped comes back to this process, and is ended in the next round. */
void reap_strays(const pid_t *keep, int keep_count)
{
    size_t room = 256;
    pid_t *list = malloc(room * sizeof *list);
    for (int rounds = 0; list != NULL; rounds++) {
        size_t count = 0;
        my_children(&list, &count, &room);
        size_t strays = 0;
        for (size_t k = 0; k < count; k++) {
            bool kept = false;
            for (int j = 0; j < keep_count; j++)
                kept |= list[k] == keep[j];
            if (!kept)
                list[strays++] = list[k];
        }
        if (strays == 0)
            break;
        /* The tree below each stray, stopped top down (the list grows as children are read),
         * then killed: a stopped process makes no child, nor does its parent hand it on. */
        count = strays;
        for (size_t k = 0; k < count; k++) {
            kill(list[k], SIGSTOP);
            children_of(list[k], &list, &count, &room);
        }
        for (size_t k = 0; k < count; k++)
            kill(list[k], SIGKILL);
        /* The direct ones are reaped when they have ended; the rest come back to be. */
        int reaped = 0;
        for (size_t k = 0; k < strays; k++)
            reaped += waitpid(list[k], NULL, WNOHANG) > 0;
        if (reaped == 0)
            usleep(rounds < 100 ? 200 : 2000);
    }
    free(list);
}
