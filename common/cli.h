/* cli.h: the command line of every part, from one table of options. */
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

/* Everything the command line sets, for every part; a part reads the fields it knows. */
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
    /* From part 1.2 on. */
    bool two_sided; /* shade back faces with their own material */
    /* From part 1.3 on. */
    int max_depth;     /* reflected (and refracted) rays a path may take */
    double ray_offset; /* where secondary rays start, relative to the coordinates */
    /* Parts 1.4 and 1.5. */
    int mode; /* the course's box modes 0-3 */
    /* From part 1.5 on. */
    const char *fresnel_name; /* how glass reflects: "schlick" (NULL: the default) or "exact" */
    double min_weight;        /* reflected and refracted rays that count less are not traced */
    /* Part 1.6. */
    int samples;               /* P: P x P primary rays per pixel */
    int light_samples;         /* S: S x S shadow rays per area light at every hit */
    int seed;                  /* picks the random numbers; the same seed, the same image */
    const char *sampling_name; /* random, jittered or correlated (the default) */
} Options;

/* excerpt: cli-option */
/* One option of one or more parts. Parts are numbered as the course numbers them,
 * 11 for part 1.1 to 16 for part 1.6. An option that the course gives as a positional
 * argument (1.4's MODE) names it: students' programs take it by position. */
typedef struct {
    const char *name; /* the long name, without dashes */
    char letter;      /* the short name, or 0 */
    OptionKind kind;
    const char *metavar; /* the value's placeholder in --help: "N", "FILE" */
    const char *help;
    size_t field;             /* offsetof(Options, ...) */
    double fallback;          /* the value when not given (kinds INT and NUMBER) */
    double min, max;          /* the values accepted (kinds INT and NUMBER) */
    int first_part, last_part; /* the parts that accept it; 0 and 0 for all */
    const char *argument;     /* the course's positional argument, or NULL */
} CliOption;
/* end excerpt: cli-option */

extern const CliOption cli_options[]; /* ended by an entry whose name is NULL */

/* What one part's program is: its name ("1.3-shadows-mirror") and one sentence for --help. */
typedef struct {
    const char *part;
    const char *purpose;
} CliSpec;

typedef enum {
    CLI_RUN,      /* render with these options */
    CLI_DONE,     /* --help or --version was answered: exit 0 */
    CLI_BAD_USAGE /* a message was printed: exit 2 */
} CliResult;

int cli_part_number(const char *part);
bool cli_option_accepted(const CliOption *o, int part);
const CliOption *cli_option_named(const char *name);
CliResult cli_parse(const CliSpec *spec, int argc, char **argv, Options *opts);
void cli_print_help(const CliSpec *spec, FILE *f);
char *cli_default_output(const char *scene_path);

#endif
