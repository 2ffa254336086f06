/* capture.h: a child's output as it comes through a pipe: its head and tail kept, the rest counted. */
#ifndef RAYTRA_CAPTURE_H
#define RAYTRA_CAPTURE_H

#include <stddef.h>

/* What the sandbox keeps of a child's output, read through a pipe: the first and the last
 * KEEP_BYTES; what lies between is counted, never stored, and a line says how much was cut. */
#define KEEP_BYTES (64 << 10)

/* A child's output as it comes: the head, then the tail in a ring, and the count of all. */
typedef struct {
    char head[KEEP_BYTES], tail[KEEP_BYTES];
    size_t head_len;
    unsigned long long total;
} Capture;

int capture_read(Capture *c, int fd);
char *capture_text(const Capture *c);

#endif
