/* grade_sandbox.h: what a student's build or run may reach: bubblewrap's walls, its environment, its disk. */
#ifndef RAYTRA_GRADE_SANDBOX_H
#define RAYTRA_GRADE_SANDBOX_H

#include <stdbool.h>

/* What a student's build or run may reach in the sandbox (namespaces): the folders it may
 * write, the files and folders it may read, beside the toolchain; and the bytes its folders
 * may hold (0: any), past which it is stopped, with either containment. */
typedef struct {
    const char *write[4]; /* NULL-ended */
    char **read;          /* NULL-ended, or NULL */
    long long disk_limit;
} View;

void sandbox_use(char *bwrap_path, bool closes);
char **sandbox_wrap(char *const argv[], const char *dir, const View *view, bool own_user);
char **sandbox_scene_files(const char *scene, const char *run_dir, char *also);
void sandbox_environment(const char *dir);
bool sandbox_over_disk(const View *view);

#endif
