/* contain.h: students' runs as users of their own (--run-as): the grader's side. */
#ifndef RAYTRA_CONTAIN_H
#define RAYTRA_CONTAIN_H

#include <stdbool.h>

bool contain_start(const char *run_as, const char *grader_user, int jobs);
int contain_users(void);
void contain_use_slot(int k);
int contain_run(char *const argv[], const char *dir, int out, long long memory_limit,
                double time_limit);
void contain_kill(void);
bool contain_answered(int answer);
bool contain_wait(int answer, int *status);
bool contain_share(const char *path);

#endif
