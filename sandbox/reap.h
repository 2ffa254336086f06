/* reap.h: ending every process a run left below the grader (a subreaper). */
#ifndef RAYTRA_REAP_H
#define RAYTRA_REAP_H

#include <sys/types.h>

void reap_strays(const pid_t *keep, int keep_count);

#endif
