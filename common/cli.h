/* cli.h: the command line of every part: the common options, and those each part declares. */
#ifndef RAYTRA_CLI_H
#define RAYTRA_CLI_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#include "image.h"
#include "scene.h"

#define RAYTRA_VERSION "0.2.0"

typedef enum {
    OPTION_FLAG,   /* no value; sets a bool */
    OPTION_INT,    /* a whole number in [min, max]; sets an int */
    OPTION_NUMBER, /* a decimal number in [min, max]; sets a double */
    OPTION_TEXT    /* any word; sets a const char * */
} OptionKind;

/* excerpt: cli-option */
/* One option. The table of common.c's options serves every part; a part adds the rows of
 * its own (and of the earlier parts whose options it keeps) through CliSpec.options. An
 * option that the course gives as a positional argument (1.4's MODE) names it: students'
 * programs take it by position. */
typedef struct {
    const char *name; /* the long name, without dashes */
    char letter;      /* the short name, or 0 */
    OptionKind kind;
    const char *metavar; /* the value's placeholder in --help: "N", "FILE" */
    const char *help;
    size_t field;         /* common options: offsetof(Options, ...); a part's: unused */
    double fallback;      /* the value when not given (kinds INT and NUMBER) */
    double min, max;      /* the values accepted (kinds INT and NUMBER) */
    const char *argument; /* the course's positional argument, or NULL */
} CliOption;
/* end excerpt: cli-option */

/* The value of one of a part's options; the option's kind says which member holds it. */
typedef union {
    bool flag;
    int whole;
    double number;
    const char *text;
} OptionValue;

enum { CLI_MAX_PART_OPTIONS = 16 };

/* Everything the command line sets: the options every part has, as fields, and the
 * part's own, read by name (cli_int, cli_number, cli_flag, cli_text). */
typedef struct {
    const char *scene;
    const char *output; /* NULL: the scene's name with .png, in the working directory */
    int threads;
    bool quiet;
    bool check_only; /* read and check the scene, then stop */
    bool linear;
    bool strict; /* a NaN or infinite pixel fails the render */
    const char *convention_name;
    Convention convention;
    bool convention_given; /* on the command line: it overrides the scene file */
    double scale;
    bool help, version;
    const char *trace_pixel;      /* "X,Y": print that pixel's ray tree, write no image */
    const char *view;             /* a debug view's name: draw it instead of the light */
    const struct Explain *explain; /* set by app_main while tracing that pixel; else NULL */
    int part_count;                /* the part's own options: */
    const CliOption *part_rows[CLI_MAX_PART_OPTIONS];
    OptionValue part_values[CLI_MAX_PART_OPTIONS];
} Options;

extern const CliOption cli_options[]; /* every part's; ended by an entry whose name is NULL */

/* What one part's program is: its name ("1.3-shadows-mirror"), one sentence for --help,
 * and the tables of its own options, each ended by an entry whose name is NULL, the
 * list ended by NULL (NULL: none). */
typedef struct {
    const char *part;
    const char *purpose;
    const CliOption *const *options;
} CliSpec;

typedef enum {
    CLI_RUN,      /* render with these options */
    CLI_DONE,     /* --help or --version was answered: exit 0 */
    CLI_BAD_USAGE /* a message was printed: exit 2 */
} CliResult;

const CliOption *cli_option_named(const CliOption *const *tables, const char *name);
const CliOption *cli_option_lettered(const CliOption *const *tables, char letter);
void cli_defaults(Options *opts, const CliOption *const *tables);
OptionValue *cli_set(Options *opts, const char *name, OptionKind kind);
bool cli_flag(const Options *opts, const char *name);
int cli_int(const Options *opts, const char *name);
double cli_number(const Options *opts, const char *name);
const char *cli_text(const Options *opts, const char *name);
CliResult cli_parse(const CliSpec *spec, int argc, char **argv, Options *opts);
void cli_print_help(const CliSpec *spec, FILE *f);
char *cli_default_output(const char *scene_path);

#endif
