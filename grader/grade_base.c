/* grade_base.c: the grader's messages of failure, and the memory and strings it keeps until it exits. */
#include "grade_base.h"

#include <stdarg.h>
#include <stdlib.h>

/* Prints "grade: " and a message made as printf makes it; returns false, to end a chain. */
bool grade_fail(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fputs("grade: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    return false;
}

/* Returns zeroed memory that lasts until the exit (what the grader gathers serves the
 * report), each block chained to the one before so that all stay reachable; exits on none. */
void *grade_alloc(size_t size)
{
    static void *last;
    void **block = calloc(1, sizeof(max_align_t) + size);
    if (block == NULL) {
        grade_fail("out of memory");
        exit(EXIT_TROUBLE);
    }
    *block = last;
    last = block;
    return (char *)block + sizeof(max_align_t);
}

/* Returns a new string made as printf makes it. */
char *grade_format(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int len = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    char *s = grade_alloc((size_t)len + 1);
    va_start(ap, fmt);
    vsnprintf(s, (size_t)len + 1, fmt, ap);
    va_end(ap);
    return s;
}

/* Returns a memory limit in words: "2 GiB", "512 MiB", or "none" for 0. */
char *grade_size_text(long long bytes)
{
    return bytes <= 0                  ? "none"
           : bytes % (1LL << 30) == 0 ? grade_format("%lld GiB", bytes >> 30)
                                      : grade_format("%lld MiB", bytes >> 20);
}
