/* lex.h: reading text files a line at a time and splitting lines into words and numbers. */
#ifndef RAYTRA_LEX_H
#define RAYTRA_LEX_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

/* Lines longer than this are reported and skipped, never stored. */
#define LEX_MAX_LINE 65536

/* A line has at most this many words kept; more are only counted. */
#define LEX_MAX_WORDS 64

/* Numbers larger than this in magnitude are refused: squaring them must not overflow. */
#define LEX_MAX_NUMBER 1e12

typedef enum {
    LINE_OK,       /* a line, without its end-of-line characters */
    LINE_END,      /* end of file */
    LINE_TOO_LONG, /* skipped: longer than LEX_MAX_LINE */
    LINE_BINARY,   /* a NUL byte or a control character: not a text file; stop reading */
    LINE_IO_ERROR, /* the file could not be read */
    LINE_STOPPED   /* a stop was requested (stop.h) in the middle of a line */
} LineStatus;

typedef struct {
    FILE *file;
    int line; /* number of the line last read, from 1 */
    char buf[LEX_MAX_LINE + 1];
    size_t length;
    int bad_byte; /* after LINE_BINARY: the byte that made it binary */
} LineReader;

typedef struct {
    int count; /* all words on the line, even those not kept */
    char *word[LEX_MAX_WORDS];
} Words;

typedef enum {
    NUMBER_OK,
    NUMBER_DASH,       /* a number, but its minus sign is a typographic dash: warn */
    NUMBER_MALFORMED,  /* not a decimal number */
    NUMBER_NOT_FINITE, /* nan, inf, or too large to represent */
    NUMBER_TOO_LARGE   /* finite but beyond LEX_MAX_NUMBER */
} NumberStatus;

/* The warning for NUMBER_DASH, shared so that scene and OBJ files count as one kind. */
extern const char lex_dash_warning[];

void lex_start(LineReader *r, FILE *file);
LineStatus lex_next_line(LineReader *r);
const char *lex_binary_byte_name(const LineReader *r);
void lex_split(char *line, Words *w);
NumberStatus lex_number(const char *word, double *value);
const char *lex_number_problem(NumberStatus s);

#endif
