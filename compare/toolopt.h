/* toolopt.h: the instructor tools' options, each described once: getopt_long's list and --help come from it. */
#ifndef RAYTRA_TOOLOPT_H
#define RAYTRA_TOOLOPT_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

/* The most options a tool may have. */
#define TOOLOPT_MAX 32

/* One option of a tool. A tool's own table may add fields after it: the functions below
 * are given the table's stride. */
typedef struct {
    const char *name;     /* the long name, without dashes */
    char letter;          /* the short name, or 0 */
    const char *value;    /* the value's placeholder in --help ("DIR"); NULL for a flag */
    const char *help;     /* its help, '\n' where a line breaks */
    const char *fallback; /* its default, shown in --help; NULL for none */
} ToolOption;

/* Takes the value of option k of the table (NULL for a flag); false (reported) to stop. */
typedef bool (*ToolOptionSet)(void *state, int k, const char *value);

bool toolopt_parse(const char *tool, const void *table, size_t stride, int count, int argc,
                   char **argv, ToolOptionSet set, void *state);
void toolopt_print(FILE *f, const void *table, size_t stride, int count);

#endif
