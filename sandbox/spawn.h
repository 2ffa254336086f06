/* spawn.h: a child started contained (a student's in the sandbox), watched under its limits, and ended with all it left. */
#ifndef RAYTRA_SPAWN_H
#define RAYTRA_SPAWN_H

#include <stdbool.h>

#include "sandbox.h"

RunResult spawn_run(char *const argv[], const char *dir, double time_limit,
                    long long memory_limit, const SandboxView *view, bool (*stopped)(void));

#endif
