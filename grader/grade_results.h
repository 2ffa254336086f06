/* grade_results.h: a submission's results as words of a results file, written and read. */
#ifndef RAYTRA_GRADE_RESULTS_H
#define RAYTRA_GRADE_RESULTS_H

#include <stdbool.h>
#include <stdio.h>

#include "grading.h"

/* The first line of a results file, with the version of its format. */
#define RESULTS_MAGIC "grade-results 5"

/* A results file being read, a line at a time, split into words. */
typedef struct {
    FILE *file;
    const char *path;
    int line;
    char *text;
    size_t size;
    char *raw; /* the line as it was, before it was split */
    char *word[64];
    int count;
    bool bad; /* a word was not as expected */
} Reader;

void results_put_text(FILE *f, const char *text);
void results_put_submission(FILE *f, const Grading *g, const Submission *s);
bool results_next_line(Reader *r);
bool results_line_is(const Reader *r, const char *key, int count);
char *results_get_text(Reader *r, int k);
char *results_get_word(Reader *r, int k);
double results_get_number(Reader *r, int k);
bool results_get_submission(Reader *r, const Grading *g, Submission *s, const char *work,
                            const char *work_name);
char *results_read_submission(const Grading *g, Submission *s, const char *path);

#endif
