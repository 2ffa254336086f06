/* child.h: a new child made ready to exec. */
#ifndef RAYTRA_CHILD_H
#define RAYTRA_CHILD_H

#include <stdbool.h>

void child_setup(const char *dir, int out, long long memory_limit, double time_limit,
                 bool student);

#endif
