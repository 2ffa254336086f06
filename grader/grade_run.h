/* grade_run.h: a child under limits (a student's in the sandbox): how it ended, what it printed. */
#ifndef RAYTRA_GRADE_RUN_H
#define RAYTRA_GRADE_RUN_H

#include "grading.h"
#include "sandbox.h"

/* The memory limit of imgdiff, which reads students' files: none under AddressSanitizer,
 * whose shadow memory no limit leaves room for. */
#if defined(__SANITIZE_ADDRESS__)
#define RUN_OWN_MEMORY(limit) ((void)(limit), 0LL)
#else
#define RUN_OWN_MEMORY(limit) (limit)
#endif

void run_init(void);
RunResult run_program(char *const argv[], const char *dir, const char *log, double time_limit,
                      long long memory_limit);
RunResult run_student(char *const argv[], const char *dir, const char *log, double time_limit,
                      long long memory_limit, const SandboxView *view);
char *run_describe(const RunResult *r);
char *run_command_line(char *const argv[], const char *dir);
char *run_quote(const char *word);
char *run_tail(const char *output);
char *run_tail_relative(const char *output, const char *work);

#endif
