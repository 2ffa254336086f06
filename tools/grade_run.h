/* grade_run.h: running a student's make or program, or a risky step of the grader, under limits. */
#ifndef RAYTRA_GRADE_RUN_H
#define RAYTRA_GRADE_RUN_H

#include <stdbool.h>
#include <stddef.h>

/* Where and how long a child may run. */
typedef struct {
    const char *dir;        /* working directory; NULL: the grader's */
    const char *log;        /* stdout and stderr go to this file, made anew; NULL: /dev/null */
    double time_limit;      /* seconds of wall-clock time; 0: no limit */
    long long memory_limit; /* bytes of address space; 0: no limit */
} RunSpec;

typedef enum {
    RUN_EXITED,     /* status is the exit status */
    RUN_KILLED,     /* status is the signal that ended it */
    RUN_TIMED_OUT,  /* the time limit was reached: the grader killed it */
    RUN_NOT_RUN,    /* the grader could not start it (fork failed) */
    RUN_INTERRUPTED /* the grader was asked to stop (SIGINT, SIGTERM, SIGHUP) */
} RunEnd;

typedef struct {
    RunEnd end;
    int status;
    double seconds;
} RunResult;

/* The exit status of a child that could not exec its program (as the shell's). */
#define RUN_EXEC_FAILED 127

/* The largest file a child may write: a program printing in a loop must not fill the disk. */
#define RUN_FILE_LIMIT (1LL << 30)

/* The memory limit of the grader's own children that read students' files (imgdiff, the
 * thumbnails): the students' limit, but none when the grader is built with
 * AddressSanitizer, whose shadow memory no limit leaves room for. */
#if defined(__SANITIZE_ADDRESS__)
#define RUN_OWN_MEMORY(limit) ((void)(limit), 0LL)
#else
#define RUN_OWN_MEMORY(limit) (limit)
#endif

void run_init(void);
RunResult run_program(char *const argv[], const RunSpec *spec);
RunResult run_function(int (*function)(void *), void *arg, const RunSpec *spec);
void run_describe(const RunResult *r, double limit, char *text, size_t size);
char *run_log_tail(const char *path);

#endif
