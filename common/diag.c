/* diag.c: error messages at once, warnings once per kind with a count. */
#include "diag.h"

#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

/* Prepares d to send messages to stream (stderr when NULL). */
void diag_init(Diag *d, FILE *stream)
{
    memset(d, 0, sizeof *d);
    d->stream = stream ? stream : stderr;
}

/* Returns the length of the valid UTF-8 sequence at s, or 0 when there is none. */
static int utf8_length(const unsigned char *s)
{
    int n = s[0] >= 0xc2 && s[0] <= 0xdf   ? 2
            : s[0] >= 0xe0 && s[0] <= 0xef ? 3
            : s[0] >= 0xf0 && s[0] <= 0xf4 ? 4
                                           : 0;
    for (int k = 1; k < n; k++)
        if ((s[k] & 0xc0) != 0x80)
            return 0;
    return n;
}

/* Copies text to out, writing bytes that are neither printable ASCII nor valid
 * UTF-8 as \xNN: a file's garbage never reaches the terminal as control codes. */
static void sanitize(const char *text, char *out, size_t size)
{
    const unsigned char *s = (const unsigned char *)text;
    size_t used = 0;
    while (*s != '\0' && used + 5 < size) {
        int n =
            *s >= 0x80 ? utf8_length(s) : (*s >= 0x20 && *s != 0x7f) || *s == '\n' || *s == '\t';
        if (n > 0) {
            memcpy(out + used, s, (size_t)n);
            used += (size_t)n;
            s += n;
        } else {
            used += (size_t)snprintf(out + used, size - used, "\\x%02x", *s++);
        }
    }
    out[used] = '\0';
}

/* Formats "path:line: " (or "path: " for line 0) and the message into out, sanitised. */
static void format_located(char *out, size_t size, const char *path, int line, const char *prefix,
                           const char *fmt, va_list ap)
{
    char buf[1024];
    int n = line > 0 ? snprintf(buf, sizeof buf, "%s:%d: %s", path, line, prefix)
                     : snprintf(buf, sizeof buf, "%s: %s", path, prefix);
    if (n >= 0 && (size_t)n < sizeof buf)
        vsnprintf(buf + n, sizeof buf - (size_t)n, fmt, ap);
    sanitize(buf, out, size);
}

/* Reports an error at path:line right away and counts it; past DIAG_MAX_ERRORS errors are
 * only counted, so that no loop can flood the terminal. */
void diag_error(Diag *d, const char *path, int line, const char *fmt, ...)
{
    if (d->errors >= DIAG_MAX_ERRORS) {
        d->errors++;
        return;
    }
    char buf[2048];
    va_list ap;
    va_start(ap, fmt);
    format_located(buf, sizeof buf, path, line, "", fmt, ap);
    va_end(ap);
    fprintf(d->stream, "%s\n", buf);
    d->errors++;
}

/* Says, once, that reading path stopped after too many errors. */
void diag_give_up(Diag *d, const char *path)
{
    if (d->gave_up)
        return;
    d->gave_up = true;
    char buf[1024], out[2048];
    snprintf(buf, sizeof buf, "%s: too many errors; stopped reading", path);
    sanitize(buf, out, sizeof out);
    fprintf(d->stream, "%s\n", out);
}

/* Records a warning; the first of each kind is kept for diag_flush. */
void diag_warn(Diag *d, const char *path, int line, const char *fmt, ...)
{
    DiagWarning *w = NULL;
    for (int k = 0; k < d->warning_kinds; k++)
        if (d->warnings[k].format == fmt)
            w = &d->warnings[k];
    if (w == NULL) {
        if (d->warning_kinds == DIAG_MAX_WARNING_KINDS)
            return;
        char buf[2048];
        va_list ap;
        va_start(ap, fmt);
        format_located(buf, sizeof buf, path, line, "warning: ", fmt, ap);
        va_end(ap);
        w = &d->warnings[d->warning_kinds++];
        w->format = fmt;
        w->first = strdup(buf);
    }
    w->count++;
}

/* Tells whether so many errors were reported that reading should stop. */
bool diag_too_many(const Diag *d)
{
    return d->errors >= DIAG_MAX_ERRORS;
}

/* Prints each kind of warning once, with how often it occurred, and forgets them. */
void diag_flush(Diag *d)
{
    for (int k = 0; k < d->warning_kinds; k++) {
        DiagWarning *w = &d->warnings[k];
        if (w->first == NULL)
            fprintf(d->stream, "warning: out of memory for a warning\n");
        else if (w->count == 1)
            fprintf(d->stream, "%s\n", w->first);
        else
            fprintf(d->stream, "%s (%d times in all)\n", w->first, w->count);
        free(w->first);
    }
    d->warning_kinds = 0;
}

/* Forgets the warnings not yet printed: after a fatal error they are noise. */
void diag_forget_warnings(Diag *d)
{
    for (int k = 0; k < d->warning_kinds; k++)
        free(d->warnings[k].first);
    d->warning_kinds = 0;
}

/* Formats a message into e, sanitised like every diagnostic. */
void error_set(Error *e, const char *fmt, ...)
{
    char buf[sizeof e->text];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    sanitize(buf, e->text, sizeof e->text);
}
