/* cli.h: the command line every part shares: raytra SCENE [OUTPUT] [options]. */
#ifndef RAYTRA_CLI_H
#define RAYTRA_CLI_H

#include <stdbool.h>
#include <stdio.h>

#include "image.h"
#include "scene.h"

#define RAYTRA_VERSION "0.1.0"

typedef enum {
    OPTION_FLAG,   /* no value; sets a bool */
    OPTION_INT,    /* a whole number in [min, max]; sets an int */
    OPTION_NUMBER, /* a number in [min, max]; sets a double */
    OPTION_TEXT    /* any word; sets a const char * */
} OptionKind;

/* An option (or, in CliSpec.arguments, a positional argument) and where its value goes. */
typedef struct {
    const char *name; /* long name without the dashes; for arguments, the placeholder */
    char letter;      /* short name, or 0 */
    OptionKind kind;
    const char *metavar; /* placeholder for the value in --help: "N", "FILE" */
    const char *help;
    void *value; /* bool *, int *, double * or const char **, by kind */
    double min, max;
} CliOption;

/* Everything the shared options set. */
typedef struct {
    const char *scene;
    const char *output; /* NULL: the scene's name with .png, in the working directory */
    int threads;
    bool quiet;
    bool check_only; /* read and check the scene, then stop */
    bool linear;
    Convention convention;
    bool convention_given; /* on the command line: it overrides the scene file */
    double scale;
    bool strict;
} Options;

/* What one part's program accepts beyond the shared options. */
typedef struct {
    const char *part;           /* "1.1-spheres-red" */
    const char *purpose;        /* one sentence for --help */
    const CliOption *options;   /* the part's own options, ended by an empty entry; or NULL */
    const CliOption *arguments; /* optional positional arguments after OUTPUT, likewise */
} CliSpec;

typedef enum {
    CLI_RUN,      /* render with these options */
    CLI_DONE,     /* --help or --version was answered: exit 0 */
    CLI_BAD_USAGE /* a message was printed: exit 2 */
} CliResult;

CliResult cli_parse(const CliSpec *spec, int argc, char **argv, Options *opts);
void cli_print_help(const CliSpec *spec, FILE *f);
char *cli_default_output(const char *scene_path);

#endif
