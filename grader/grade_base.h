/* grade_base.h: the grader's messages of failure, its exit statuses, the memory and strings it keeps. */
#ifndef RAYTRA_GRADE_BASE_H
#define RAYTRA_GRADE_BASE_H

#include <stdbool.h>
#include <stddef.h>

#include "diag.h"

/* The grader's exit statuses: the report written (whatever the verdicts), trouble, a stop. */
enum { EXIT_REPORTED = 0, EXIT_TROUBLE = 2, EXIT_INTERRUPTED = 130 };

void *grade_alloc(size_t size);
char *grade_format(const char *fmt, ...) DIAG_PRINTF(1, 2);
bool grade_fail(const char *fmt, ...) DIAG_PRINTF(1, 2);
char *grade_size_text(long long bytes);

#endif
