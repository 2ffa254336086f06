/* sandbox.h: what a student's build or run may reach (bubblewrap's walls or the fallback's), and how the sandbox tells its trouble. */
#ifndef RAYTRA_SANDBOX_H
#define RAYTRA_SANDBOX_H

#include <stdbool.h>

/* What a student's build or run may reach in the sandbox (namespaces): the folders it may
 * write, the files and folders it may read, beside the toolchain; and the bytes its folders
 * may hold (0: any), past which it is stopped, with either containment. */
typedef struct {
    const char *write[4]; /* NULL-ended */
    char **read;          /* NULL-ended, or NULL */
    long long disk_limit;
} SandboxView;

/* How a run ended: status is the exit status (RUN_EXITED), the signal (RUN_KILLED) or the
 * errno (RUN_NOT_RUN: fork or pipe failed); ok when it exited with status 0; output what it
 * printed, its head and tail when it printed more than the sandbox keeps (never NULL; it
 * lasts until the next run). */
typedef enum {
    RUN_EXITED, RUN_KILLED, RUN_TIMED_OUT, RUN_NOT_RUN, RUN_INTERRUPTED,
    RUN_OVER_DISK /* a student's run stopped: it wrote past its disk limit, or filled the disk */
} RunEnd;

typedef struct {
    RunEnd end;
    int status;
    double seconds;
    bool ok;
    char *output;
} RunResult;

/* The exit status of a child that could not exec its program (as the shell's). */
#define SANDBOX_EXEC_FAILED 127

void sandbox_tell_as(const char *program);
const char *sandbox_teller(void);
bool sandbox_fail(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
void sandbox_use(char *bwrap_path, bool closes);
bool sandbox_namespaces(void);
char **sandbox_wrap(char *const argv[], const char *dir, const SandboxView *view, bool own_user);
void sandbox_environment(const char *dir);
bool sandbox_over_disk(const SandboxView *view);

#endif
