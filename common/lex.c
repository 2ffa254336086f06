/* lex.c: line reading that survives CRLF, tabs, NUL bytes and huge lines. */
#include "lex.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "stop.h"

/* Prepares r to read file from its first line. */
void lex_start(LineReader *r, FILE *file)
{
    r->file = file;
    r->line = 0;
    r->length = 0;
    r->bad_byte = 0;
    r->buf[0] = '\0';
}

/* Tells whether byte c never appears in a text file: a NUL, or a control code other than
 * the blanks (tab, line feed, vertical tab, form feed, carriage return) and the escape
 * and end-of-file (Ctrl-Z) codes that old editors leave. */
static bool is_binary_byte(int c)
{
    return (c >= 0 && c < 0x09) || (c > 0x0d && c < 0x1a) || (c > 0x1b && c < 0x20) ||
           c == 0x7f;
}

/* Reads the next line into r->buf, dropping "\n" or "\r\n". A binary byte ends the
 * reading at once, without looking for a newline that may never come (/dev/zero); a
 * stop request (stop.h) ends it too, every 64 KiB, so that even an endless line can be
 * interrupted. */
LineStatus lex_next_line(LineReader *r)
{
    size_t n = 0, seen = 0;
    bool too_long = false;
    int c;
    /* The reader is the file's only user: no need to lock the stream for every byte. */
    while ((c = getc_unlocked(r->file)) != EOF && c != '\n') {
        if (is_binary_byte(c)) {
            /* What came before the byte stays in buf: a file's first bytes name its type. */
            r->line++;
            r->buf[n] = '\0';
            r->length = n;
            r->bad_byte = c;
            return LINE_BINARY;
        }
        if (n < LEX_MAX_LINE)
            r->buf[n++] = (char)c;
        else
            too_long = true;
        if (++seen % LEX_MAX_LINE == 0 && stop_requested())
            return LINE_STOPPED;
    }
    if (c == EOF && ferror(r->file))
        return LINE_IO_ERROR;
    if (c == EOF && n == 0 && !too_long)
        return LINE_END;
    r->line++;
    if (n > 0 && r->buf[n - 1] == '\r')
        n--;
    r->buf[n] = '\0';
    r->length = n;
    return too_long ? LINE_TOO_LONG : LINE_OK;
}

/* Describes the binary byte that ended the reading, for "...: this is not a text file". */
const char *lex_binary_byte_name(const LineReader *r)
{
    static const char *const names[] = {"NUL byte", "control character"};
    return names[r->bad_byte != 0];
}

/* Splits line in place into words separated by blanks (spaces, tabs, ...). */
void lex_split(char *line, Words *w)
{
    w->count = 0;
    char *p = line;
    for (;;) {
        while (*p != '\0' && isspace((unsigned char)*p))
            p++;
        if (*p == '\0')
            return;
        if (w->count < LEX_MAX_WORDS)
            w->word[w->count] = p;
        w->count++;
        while (*p != '\0' && !isspace((unsigned char)*p))
            p++;
        if (*p != '\0')
            *p++ = '\0';
    }
}

/* Tells whether word is a plain decimal number: [+-] digits [. digits] [e [+-] digits]. */
static bool is_decimal(const char *s)
{
    int digits = 0;
    if (*s == '+' || *s == '-')
        s++;
    for (; isdigit((unsigned char)*s); s++)
        digits++;
    if (*s == '.')
        for (s++; isdigit((unsigned char)*s); s++)
            digits++;
    if (digits == 0)
        return false;
    if (*s == 'e' || *s == 'E') {
        s++;
        if (*s == '+' || *s == '-')
            s++;
        if (!isdigit((unsigned char)*s))
            return false;
        while (isdigit((unsigned char)*s))
            s++;
    }
    return *s == '\0';
}

/* Reads word when it is a plain decimal of at most 15 digits, [+-] digits [. digits],
 * the form of nearly every number of an OBJ file, faster than strtod and to the same
 * double: the digits make an integer m < 10^15 < 2^53 and 10^k (k <= 15) is exact too,
 * so m / 10^k is a single correctly rounded division, as strtod's answer is. False for
 * anything else, which strtod reads. */
static bool fast_decimal(const char *s, double *value)
{
    static const double pow10[16] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                     1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
    bool negative = *s == '-';
    if (*s == '+' || *s == '-')
        s++;
    long long m = 0;
    int digits = 0, fraction = 0;
    /* More than 15 digits go to strtod, before m could overflow. */
    for (; isdigit((unsigned char)*s); s++, digits++) {
        if (digits == 15)
            return false;
        m = 10 * m + (*s - '0');
    }
    if (*s == '.') {
        for (s++; isdigit((unsigned char)*s); s++, digits++, fraction++) {
            if (digits == 15)
                return false;
            m = 10 * m + (*s - '0');
        }
    }
    if (*s != '\0' || digits == 0)
        return false;
    double v = (double)m / pow10[fraction];
    *value = negative ? -v : v;
    return true;
}

const char lex_dash_warning[] = "'%s' has a dash where a minus sign belongs; read as %g";

/* Byte sequences that word processors and input methods put where a minus sign belongs. */
static const char *const dashes[] = {
    "\xe2\x80\x90", "\xe2\x80\x91",
    "\xe2\x80\x92", /* UTF-8 hyphen, non-breaking hyphen, figure dash */
    "\xe2\x80\x93", "\xe2\x80\x94",
    "\xe2\x80\x95",                 /* UTF-8 en dash, em dash, horizontal bar */
    "\xe2\x88\x92", "\xef\xbc\x8d", /* UTF-8 minus sign, fullwidth hyphen-minus */
    "\xa1\xaa",     "\xa3\xad",     /* GB2312 em dash and fullwidth minus */
    "\x96",         "\x97",         /* Windows-1252 en and em dash */
};

/* Returns the length of the dash word starts with, or 0 when it starts with none. */
static size_t dash_length(const char *word)
{
    for (size_t k = 0; k < sizeof dashes / sizeof dashes[0]; k++) {
        size_t len = strlen(dashes[k]);
        if (strncmp(word, dashes[k], len) == 0)
            return len;
    }
    return 0;
}

/* Reads word as a decimal number; hexadecimal, "nan" and "inf" are refused. A
 * typographic dash in place of the minus sign is read as one (NUMBER_DASH). */
NumberStatus lex_number(const char *word, double *value)
{
    size_t dash = dash_length(word);
    if (dash > 0 && (isdigit((unsigned char)word[dash]) || word[dash] == '.')) {
        NumberStatus s = lex_number(word + dash, value);
        if (s != NUMBER_OK)
            return s;
        *value = -*value;
        return NUMBER_DASH;
    }
    double v;
    if (fast_decimal(word, &v)) {
        if (fabs(v) > LEX_MAX_NUMBER)
            return NUMBER_TOO_LARGE;
        *value = v;
        return NUMBER_OK;
    }
    if (!is_decimal(word)) {
        const char *s = word + (*word == '+' || *word == '-');
        if (strncasecmp(s, "nan", 3) == 0 || strncasecmp(s, "inf", 3) == 0)
            return NUMBER_NOT_FINITE;
        return NUMBER_MALFORMED;
    }
    v = strtod(word, NULL);
    if (!isfinite(v))
        return NUMBER_NOT_FINITE;
    if (fabs(v) > LEX_MAX_NUMBER)
        return NUMBER_TOO_LARGE;
    *value = v;
    return NUMBER_OK;
}

/* Describes what is wrong with a number, for messages like "got 'abc': <this>". */
const char *lex_number_problem(NumberStatus s)
{
    switch (s) {
    case NUMBER_OK: return "fine";
    case NUMBER_DASH: return "a number whose minus sign is a dash";
    case NUMBER_MALFORMED: return "not a number";
    case NUMBER_NOT_FINITE: return "not a finite number";
    case NUMBER_TOO_LARGE: return "too large (the limit is 1e12)";
    }
    return "not a number";
}
