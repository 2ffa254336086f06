/* toolopt.c: reading a tool's options with getopt_long, and listing them for --help, from one table. */
#include "toolopt.h"

#include <getopt.h>

/* The column where the options' help starts in --help. */
#define HELP_COLUMN 26

/* Returns entry k of a table whose entries, stride bytes apart, each begin with a ToolOption. */
static const ToolOption *entry(const void *table, size_t stride, int k)
{
    return (const ToolOption *)((const char *)table + (size_t)k * stride);
}

/* Reads the options of argv with getopt_long (they may follow the other words, which it
 * leaves from optind on), calling set for each; false when one is unknown, lacks its value,
 * or set refuses it, with a message "TOOL: ..." for the first two. */
bool toolopt_parse(const char *tool, const void *table, size_t stride, int count, int argc,
                   char **argv, ToolOptionSet set, void *state)
{
    struct option longs[TOOLOPT_MAX + 1] = {{0}};
    char shorts[2 * TOOLOPT_MAX + 2] = ":"; /* ':' first: a missing value is told apart */
    size_t len = 1;
    for (int k = 0; k < count && k < TOOLOPT_MAX; k++) {
        const ToolOption *o = entry(table, stride, k);
        /* A short option reports its letter, a long one 0 and its index in longs. */
        longs[k] = (struct option){o->name, o->value != NULL ? required_argument : no_argument,
                                   NULL, 0};
        if (o->letter != 0) {
            shorts[len++] = o->letter;
            if (o->value != NULL)
                shorts[len++] = ':';
        }
    }
    shorts[len] = '\0';
    opterr = 0;
    int c, k = 0;
    while ((c = getopt_long(argc, argv, shorts, longs, &k)) != -1) {
        if (c == ':' || c == '?') {
            fprintf(stderr,
                    c == ':' ? "%s: %s needs a value\n"
                             : "%s: unknown option '%s' (%s --help lists them)\n",
                    tool, argv[optind - 1], tool);
            return false;
        }
        for (int s = 0; c != 0 && s < count; s++)
            if (entry(table, stride, s)->letter == c)
                k = s;
        if (!set(state, k, optarg))
            return false;
    }
    return true;
}

/* Prints the table as the options part of --help: "  -q, --quiet" or "  --out DIR", its
 * help from HELP_COLUMN on, and its default when it has one. */
void toolopt_print(FILE *f, const void *table, size_t stride, int count)
{
    for (int k = 0; k < count; k++) {
        const ToolOption *o = entry(table, stride, k);
        int n = o->letter != 0 ? fprintf(f, "  -%c, --%s", o->letter, o->name)
                               : fprintf(f, "  --%s", o->name);
        if (o->value != NULL)
            n += fprintf(f, " %s", o->value);
        fprintf(f, "%*s", n < HELP_COLUMN ? HELP_COLUMN - n : 1, "");
        for (const char *p = o->help; *p != '\0'; p++)
            if (*p == '\n')
                fprintf(f, "\n%*s", HELP_COLUMN, "");
            else
                fputc(*p, f);
        fprintf(f, o->fallback != NULL ? " (default %s)\n" : "\n", o->fallback);
    }
}
