/* diag.h: messages about bad input, in the form file:line: what is wrong. */
#ifndef RAYTRA_DIAG_H
#define RAYTRA_DIAG_H

#include <stdbool.h>
#include <stdio.h>

/* After this many errors in one file, reading stops: the rest is noise. */
#define DIAG_MAX_ERRORS 20

/* Warnings of one kind (one format string) are told once, with a count. */
#define DIAG_MAX_WARNING_KINDS 32

typedef struct {
    const char *format; /* identifies the kind */
    char *first;        /* the first warning of this kind, formatted */
    int count;
} DiagWarning;

typedef struct {
    FILE *stream; /* where messages go */
    int errors;
    bool gave_up; /* "too many errors" was said */
    int warning_kinds;
    DiagWarning warnings[DIAG_MAX_WARNING_KINDS];
} Diag;

/* A message for a caller that reports it in its own way. */
typedef struct {
    char text[512];
} Error;

#if defined(__GNUC__)
#define DIAG_PRINTF(f, a) __attribute__((format(printf, f, a)))
#else
#define DIAG_PRINTF(f, a)
#endif

void diag_init(Diag *d, FILE *stream);
void diag_error(Diag *d, const char *path, int line, const char *fmt, ...) DIAG_PRINTF(4, 5);
void diag_warn(Diag *d, const char *path, int line, const char *fmt, ...) DIAG_PRINTF(4, 5);
bool diag_too_many(const Diag *d);
void diag_give_up(Diag *d, const char *path);
void diag_flush(Diag *d);
void diag_forget_warnings(Diag *d);
void error_set(Error *e, const char *fmt, ...) DIAG_PRINTF(2, 3);

#endif
