/* capture.c: a child's output as it comes through a pipe: its head and tail kept, the rest counted. */
#define _GNU_SOURCE /* stpcpy */
#include "capture.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "sandbox.h"

/* Adds n bytes of output to the capture: to the head until it is full, then to the ring. */
static void capture_add(Capture *c, const char *bytes, size_t n)
{
    size_t to_head = c->head_len < KEEP_BYTES ? KEEP_BYTES - c->head_len : 0;
    to_head = to_head < n ? to_head : n;
    memcpy(c->head + c->head_len, bytes, to_head);
    c->head_len += to_head;
    for (size_t k = to_head; k < n;) {
        size_t at = (size_t)((c->total + k - c->head_len) % KEEP_BYTES);
        size_t run = KEEP_BYTES - at < n - k ? KEEP_BYTES - at : n - k;
        memcpy(c->tail + at, bytes + k, run);
        k += run;
    }
    c->total += n;
}

/* Reads what the pipe holds into the capture, at most 4 MiB at a time so that the limits are
 * looked at again; returns the descriptor, or -1 once it is closed at the end of the output. */
int capture_read(Capture *c, int fd)
{
    char chunk[1 << 16];
    for (int k = 0; k < 64; k++) {
        ssize_t n = read(fd, chunk, sizeof chunk);
        if (n > 0)
            capture_add(c, chunk, (size_t)n);
        else if (n < 0 && errno == EINTR)
            continue;
        else if (n < 0 && errno == EAGAIN)
            return fd;
        else {
            close(fd);
            return -1;
        }
    }
    return fd;
}

/* Returns what the capture kept as one string: the head, a line saying how many bytes were
 * cut when some were, and the tail; a NUL byte the program printed becomes '?'. The string
 * lasts until the next call, so that a class of programs that print much takes no more
 * memory than one. */
char *capture_text(const Capture *c)
{
    static char text[2 * KEEP_BYTES + 256];
    size_t rest = (size_t)(c->total - c->head_len); /* the bytes after the head */
    size_t tail = rest < KEEP_BYTES ? rest : KEEP_BYTES;
    unsigned long long cut = c->total - c->head_len - tail;
    char note[200] = "";
    if (cut > 0)
        snprintf(note, sizeof note,
                 "\n[%s: %llu bytes cut here: of the %llu bytes printed, "
                 "the first and the last %d KiB are kept]\n",
                 sandbox_teller(), cut, c->total, KEEP_BYTES >> 10);
    size_t len = c->head_len + strlen(note) + tail;
    char *t = text;
    memcpy(t, c->head, c->head_len);
    t = stpcpy(t + c->head_len, note);
    for (size_t k = 0, from = (size_t)((c->total - tail - c->head_len) % KEEP_BYTES); k < tail; k++)
        *t++ = c->tail[(from + k) % KEEP_BYTES];
    for (size_t k = 0; k < len; k++)
        text[k] = text[k] == '\0' ? '?' : text[k];
    text[len] = '\0';
    return text;
}
