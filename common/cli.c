/* cli.c: the options every part has, and parsing them with a part's own by getopt_long. */
#include "cli.h"

#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "render.h"

#define FIELD(name) offsetof(Options, name)

/* excerpt: cli-options */
/* clang-format off */
const CliOption cli_options[] = {
    {.name = "output", .letter = 'o', .kind = OPTION_TEXT, .metavar = "FILE",
     .help = "write the image to FILE (same as OUTPUT)", .field = FIELD(output)},
    {.name = "threads", .letter = 'j', .kind = OPTION_INT, .metavar = "N",
     .help = "render with N threads (default: one per core)", .field = FIELD(threads),
     .min = 1, .max = 256},
    {.name = "quiet", .letter = 'q', .help = "no progress bar and no summary line",
     .field = FIELD(quiet)},
    {.name = "check",
     .help = "read and check the scene, say what it holds, and exit without rendering",
     .field = FIELD(check_only)},
    {.name = "convention", .kind = OPTION_TEXT, .metavar = "NAME",
     .help = "read planes and point lights by convention NAME: lecture (p.N + d = 0, no "
             "falloff; the default) or fall2016 (p.N = d, 1/r^2 falloff); overrides an "
             "'o convention' line",
     .field = FIELD(convention_name)},
    {.name = "scale", .kind = OPTION_NUMBER, .metavar = "F",
     .help = "multiply the camera's pixel counts by F (0.25 for a quick look)",
     .field = FIELD(scale), .fallback = 1, .min = 1e-3, .max = 64},
    {.name = "linear", .help = "write PNG values linearly, without the sRGB curve",
     .field = FIELD(linear)},
    {.name = "strict", .help = "fail (exit 1) when a pixel comes out NaN or infinite",
     .field = FIELD(strict)},
    {.name = "trace-pixel", .kind = OPTION_TEXT, .metavar = "X,Y",
     .help = "print the ray tree of the pixel in column X, row Y (0,0 is the top-left "
             "corner, as in image viewers) and write no image; where a part samples "
             "pixels, X,Y@K traces its sample K alone: K from 0 to P x P - 1, the "
             "sub-squares of the pixel counted row by row from its bottom left",
     .field = FIELD(trace_pixel)},
    {.name = "view", .kind = OPTION_TEXT, .metavar = "NAME",
     .help = "draw what each camera ray meets instead of its light: normal, depth, id "
             "(a colour per surface), material (kd), light-count (the lights that reach the "
             "point, where a part has lights), box-tests (where a part has boxes: a heat "
             "map of the boxes and primitives each camera ray is tested against)",
     .field = FIELD(view)},
    {0},
};

/* The options every part has that --help lists last, after the part's own. */
static const CliOption closing_options[] = {
    {.name = "help", .letter = 'h', .help = "show this help and exit", .field = FIELD(help)},
    {.name = "version", .help = "show the version and exit", .field = FIELD(version)},
    {0},
};
/* clang-format on */
/* end excerpt: cli-options */

enum { MAX_OPTIONS = 64 };

/* Lists in list[] the options of a part whose own are tables (a NULL-ended list of
 * tables, or NULL): the common ones, its own, then --help and --version; returns how
 * many. */
static int every_option(const CliOption *const *tables, const CliOption **list)
{
    int n = 0;
    for (const CliOption *o = cli_options; o->name != NULL && n < MAX_OPTIONS; o++)
        list[n++] = o;
    for (int t = 0; tables != NULL && tables[t] != NULL; t++)
        for (const CliOption *o = tables[t]; o->name != NULL && n < MAX_OPTIONS; o++)
            list[n++] = o;
    for (const CliOption *o = closing_options; o->name != NULL && n < MAX_OPTIONS; o++)
        list[n++] = o;
    return n;
}

/* Returns the option named name of a part whose own options are tables, or NULL. */
const CliOption *cli_option_named(const CliOption *const *tables, const char *name)
{
    const CliOption *list[MAX_OPTIONS];
    int n = every_option(tables, list);
    for (int k = 0; k < n; k++)
        if (strcmp(list[k]->name, name) == 0)
            return list[k];
    return NULL;
}

/* Returns the option whose short name is letter, as cli_option_named does, or NULL. */
const CliOption *cli_option_lettered(const CliOption *const *tables, char letter)
{
    const CliOption *list[MAX_OPTIONS];
    int n = every_option(tables, list);
    for (int k = 0; letter != 0 && k < n; k++)
        if (list[k]->letter == letter)
            return list[k];
    return NULL;
}

/* Tells whether text is a plain decimal number: digits, a point, an exponent; no
 * hexadecimal, no "inf" or "nan", as in scene files. */
static bool decimal_text(const char *text)
{
    return text[0] != '\0' && strspn(text, "0123456789+-.eE") == strlen(text);
}

/* Returns where the value of option o is kept in opts: a field of its own for a common
 * option, a slot of part_values for one of the part's. */
static void *value_of(Options *opts, const CliOption *o)
{
    for (int k = 0; k < opts->part_count; k++)
        if (opts->part_rows[k] == o)
            return &opts->part_values[k];
    return (char *)opts + o->field;
}

/* Stores text as the value of option o in opts; false (reported) when it is not valid. */
static bool set_value(const CliOption *o, const char *shown, const char *text, Options *opts)
{
    char *at = value_of(opts, o);
    char *end;
    switch (o->kind) {
    case OPTION_FLAG: *(bool *)at = true; return true;
    case OPTION_TEXT: *(const char **)at = text; return true;
    case OPTION_INT: {
        errno = 0;
        long v = strtol(text, &end, 10);
        if (!decimal_text(text) || *end != '\0' || errno != 0 || v < o->min || v > o->max) {
            fprintf(stderr, "raytra: %s takes a whole number from %.0f to %.0f, got '%s'\n", shown,
                    o->min, o->max, text);
            return false;
        }
        *(int *)at = (int)v;
        return true;
    }
    case OPTION_NUMBER: {
        double v = strtod(text, &end);
        if (!decimal_text(text) || *end != '\0' || !isfinite(v) || v < o->min || v > o->max) {
            fprintf(stderr, "raytra: %s takes a number from %g to %g, got '%s'\n", shown, o->min,
                    o->max, text);
            return false;
        }
        *(double *)at = v;
        return true;
    }
    }
    return false;
}

/* Stores the value option o has when not given. */
static void set_fallback(Options *opts, const CliOption *o)
{
    void *at = value_of(opts, o);
    if (o->kind == OPTION_INT)
        *(int *)at = (int)o->fallback;
    else if (o->kind == OPTION_NUMBER)
        *(double *)at = o->fallback;
}

/* Sets opts up for the common options and the part's, tables (a NULL-ended list of
 * tables of rows, or NULL), each at its value when not given. */
void cli_defaults(Options *opts, const CliOption *const *tables)
{
    memset(opts, 0, sizeof *opts);
    for (int t = 0; tables != NULL && tables[t] != NULL; t++)
        for (const CliOption *o = tables[t]; o->name != NULL; o++) {
            if (opts->part_count == CLI_MAX_PART_OPTIONS) {
                fprintf(stderr, "raytra: more than %d options of a part\n", CLI_MAX_PART_OPTIONS);
                abort();
            }
            opts->part_rows[opts->part_count++] = o;
        }
    const CliOption *list[MAX_OPTIONS];
    int n = every_option(tables, list);
    for (int k = 0; k < n; k++)
        set_fallback(opts, list[k]);
}

/* Returns the value of the part's option name, which must be of kind kind: a part asks
 * only for the options it declares, so anything else is a bug, and stops the program. */
static OptionValue *part_value(const Options *opts, const char *name, OptionKind kind)
{
    for (int k = 0; k < opts->part_count; k++)
        if (strcmp(opts->part_rows[k]->name, name) == 0 && opts->part_rows[k]->kind == kind)
            return (OptionValue *)&opts->part_values[k];
    fprintf(stderr, "raytra: bug: the part reads an option '%s' of another kind, or that it "
                    "does not declare\n",
            name);
    abort();
}

/* Returns the value of the part's option name, to set (unit tests set options so). */
OptionValue *cli_set(Options *opts, const char *name, OptionKind kind)
{
    return part_value(opts, name, kind);
}

/* Returns the value of the part's flag name. */
bool cli_flag(const Options *opts, const char *name)
{
    return part_value(opts, name, OPTION_FLAG)->flag;
}

/* Returns the value of the part's whole-number option name. */
int cli_int(const Options *opts, const char *name)
{
    return part_value(opts, name, OPTION_INT)->whole;
}

/* Returns the value of the part's decimal option name. */
double cli_number(const Options *opts, const char *name)
{
    return part_value(opts, name, OPTION_NUMBER)->number;
}

/* Returns the value of the part's text option name: NULL when not given. */
const char *cli_text(const Options *opts, const char *name)
{
    return part_value(opts, name, OPTION_TEXT)->text;
}

/* What cli_parse has read so far: the options the part accepts, and which of them were
 * given a value, where (the word's index in argv; 0: not given) and as what text. */
typedef struct {
    int count;
    const CliOption *accepted[MAX_OPTIONS];
    int given_at[MAX_OPTIONS];
    const char *given[MAX_OPTIONS];
} Seen;

/* Tells whether text is a negative number ("-1", "-.5"): a value, never an option. */
static bool negative_number(const char *text)
{
    return text[0] == '-' && text[1] != '\0' && strchr("0123456789.", text[1]) != NULL &&
           decimal_text(text + 1);
}

/* Stores text, the word argv[at], as the value of option o (called shown in messages).
 * A second value for an option is refused, even an equal one, as OUTPUT twice always
 * was: which one was meant cannot be told. A flag may be repeated. False (reported) on
 * a second value or a value that is not valid. */
static bool take_value(Seen *seen, const CliOption *o, const char *shown, int at, const char *text,
                       Options *opts)
{
    int k = 0;
    while (k < seen->count && seen->accepted[k] != o)
        k++;
    if (k < seen->count && o->kind != OPTION_FLAG) {
        if (seen->given_at[k] != 0) {
            bool earlier = seen->given_at[k] < at;
            const char *first = earlier ? seen->given[k] : text;
            const char *second = earlier ? text : seen->given[k];
            char what[64];
            if (strcmp(o->name, "output") == 0)
                snprintf(what, sizeof what, "the output");
            else if (o->argument != NULL)
                snprintf(what, sizeof what, "%s (--%s)", o->argument, o->name);
            else
                snprintf(what, sizeof what, "--%s", o->name);
            fprintf(stderr, "raytra: %s is given twice ('%s' and '%s'); give it once\n", what,
                    first, second);
            return false;
        }
        seen->given_at[k] = at;
        seen->given[k] = text;
    }
    return set_value(o, shown, text, opts);
}

/* Handles the k-th positional argument, the word argv[at]: SCENE, OUTPUT (the option
 * --output), then the part's own in order (each the same as its option). */
static bool set_positional(Seen *seen, int k, int at, const char *arg, Options *opts)
{
    if (k == 0) {
        opts->scene = arg;
        return true;
    }
    int seen_args = 1;
    for (int j = 0; j < seen->count; j++) {
        const CliOption *o = seen->accepted[j];
        if ((o->argument != NULL || strcmp(o->name, "output") == 0) && seen_args++ == k)
            return take_value(seen, o, o->argument != NULL ? o->argument : "OUTPUT", at, arg, opts);
    }
    fprintf(stderr, "raytra: unexpected argument '%s' (raytra --help shows the usage)\n", arg);
    return false;
}

/* Reports the option getopt_long refused: argv[optind - 1] is the word it was reading. */
static void report_refused(int argc, char **argv, int optopt_seen, const struct option *longs,
                           int index_seen)
{
    const char *word = optind - 1 < argc ? argv[optind - 1] : "";
    if (optopt_seen == ':' || (index_seen >= 0 && longs[index_seen].has_arg))
        fprintf(stderr, "raytra: option '%s' needs a value\n", word);
    else
        fprintf(stderr, "raytra: unknown option or wrong use of '%s' (raytra --help lists them)\n",
                word);
}

/* Reads argv into opts: the options this part accepts, anywhere, then the positional
 * arguments in order. The words are read in order ("-" in getopt's optstring), so that
 * positional arguments keep their places, and a negative number is taken as a positional
 * argument, to be refused as a value like 0, not as an unknown option. */
CliResult cli_parse(const CliSpec *spec, int argc, char **argv, Options *opts)
{
    cli_defaults(opts, spec->options);
    Seen seen = {0};
    seen.count = every_option(spec->options, seen.accepted);
    int n = seen.count;
    const CliOption *const *accepted = seen.accepted;

    /* getopt_long's tables: option k returns 256 + k. */
    struct option longs[MAX_OPTIONS + 1];
    char shorts[2 * MAX_OPTIONS + 3] = "-:";
    for (int k = 0; k < n; k++) {
        bool valued = accepted[k]->kind != OPTION_FLAG;
        longs[k] = (struct option){accepted[k]->name, valued ? required_argument : no_argument,
                                   NULL, 256 + k};
        if (accepted[k]->letter != 0) {
            size_t len = strlen(shorts);
            shorts[len] = accepted[k]->letter;
            shorts[len + 1] = valued ? ':' : '\0';
            shorts[len + 2] = '\0';
        }
    }
    longs[n] = (struct option){0};

    /* The positional arguments, by their index in argv, read once the options are. */
    int *positional = malloc(((size_t)argc + 1) * sizeof *positional);
    if (positional == NULL) {
        fprintf(stderr, "raytra: out of memory\n");
        return CLI_BAD_USAGE;
    }
    int positional_count = 0;
    CliResult result = CLI_BAD_USAGE;
    opterr = 0;
    optind = 0; /* glibc: start afresh, also on a second call */
    int c, index = -1;
    for (;;) {
        /* optind is 0 only before the first word, which getopt reads itself. */
        while (optind > 0 && optind < argc && negative_number(argv[optind]))
            positional[positional_count++] = optind++;
        if ((c = getopt_long(argc, argv, shorts, longs, &index)) == -1)
            break;
        if (c == 1) {
            positional[positional_count++] = optind - 1;
            continue;
        }
        const CliOption *o = NULL;
        if (c >= 256)
            o = accepted[c - 256];
        else
            for (int k = 0; k < n; k++)
                if (c != '?' && c != ':' && accepted[k]->letter == c)
                    o = accepted[k];
        if (o == NULL) {
            report_refused(argc, argv, c, longs, index);
            goto done;
        }
        char shown[64];
        snprintf(shown, sizeof shown, "--%s", o->name);
        /* optind - 1 is the value's word: the option's own ("-j4") or the next one. */
        if (!take_value(&seen, o, shown, optind - 1, optarg, opts))
            goto done;
        index = -1;
    }
    /* The words after "--" are positional, whatever they look like. */
    while (optind < argc)
        positional[positional_count++] = optind++;
    if (opts->help) {
        cli_print_help(spec, stdout);
        result = CLI_DONE;
        goto done;
    }
    if (opts->version) {
        printf("raytra %s (part %s)\n", RAYTRA_VERSION, spec->part);
        result = CLI_DONE;
        goto done;
    }
    for (int k = 0; k < positional_count; k++)
        if (!set_positional(&seen, k, positional[k], argv[positional[k]], opts))
            goto done;
    if (opts->scene == NULL) {
        fprintf(stderr, "raytra: no scene file given\nusage: raytra SCENE [OUTPUT] [options]"
                        " (raytra --help for more)\n");
        goto done;
    }
    if (opts->convention_name != NULL) {
        if (!convention_from_name(opts->convention_name, &opts->convention)) {
            fprintf(stderr, "raytra: unknown convention '%s' (lecture or fall2016)\n",
                    opts->convention_name);
            goto done;
        }
        opts->convention_given = true;
    }
    if (opts->threads == 0)
        opts->threads = render_default_threads();
    result = CLI_RUN;
done:
    free(positional);
    return result;
}

/* Prints one entry of the help: the name column, then the text wrapped beside it. */
static void print_entry(FILE *f, const char *left, const char *help)
{
    enum { COLUMN = 24, WIDTH = 79 };
    int used = fprintf(f, "  %s", left);
    const char *p = help;
    while (*p != '\0') {
        if (used >= COLUMN) {
            fputc('\n', f);
            used = 0;
        }
        fprintf(f, "%*s", COLUMN - used, "");
        int room = WIDTH - COLUMN, len = (int)strlen(p);
        if (len > room) {
            len = room;
            while (len > 0 && p[len] != ' ')
                len--;
            if (len == 0)
                len = room;
        }
        fprintf(f, "%.*s\n", len, p);
        p += len;
        while (*p == ' ')
            p++;
        used = 0;
    }
    if (used > 0)
        fputc('\n', f);
}

/* Prints the usage, the arguments and every option this part accepts, with its help. */
void cli_print_help(const CliSpec *spec, FILE *f)
{
    const CliOption *accepted[MAX_OPTIONS];
    int n = every_option(spec->options, accepted);
    fprintf(f, "usage: raytra SCENE [OUTPUT]");
    for (int k = 0; k < n; k++)
        if (accepted[k]->argument != NULL)
            fprintf(f, " [%s]", accepted[k]->argument);
    fprintf(f, " [options]\n\nraytra %s, part %s: %s\n\narguments:\n", RAYTRA_VERSION, spec->part,
            spec->purpose);
    print_entry(f, "SCENE", "the scene file to render (see docs/scene-format.md)");
    print_entry(f, "OUTPUT",
                "the image to write: .png (8-bit sRGB), .pfm (32-bit float, linear) or .exr "
                "(OpenEXR, linear); default: the scene's name with .png, in the working "
                "directory");
    for (int k = 0; k < n; k++)
        if (accepted[k]->argument != NULL) {
            char help[256];
            snprintf(help, sizeof help, "the same as --%s", accepted[k]->name);
            print_entry(f, accepted[k]->argument, help);
        }
    fprintf(f, "\noptions:\n");
    for (int k = 0; k < n; k++) {
        const CliOption *o = accepted[k];
        char left[64];
        snprintf(left, sizeof left, "%c%c%c --%s%s%s", o->letter ? '-' : ' ',
                 o->letter ? o->letter : ' ', o->letter ? ',' : ' ', o->name, o->metavar ? " " : "",
                 o->metavar ? o->metavar : "");
        print_entry(f, left, o->help);
    }
    fprintf(f, "\nexit status: 0 when the image was written, 1 when the scene or the output\n"
               "has a problem (the message says what and where), 2 for a bad command line,\n"
               "130 or 143 when interrupted (nothing is written then).\n");
}

/* Returns (to free) the scene's file name with its extension replaced by .png. */
char *cli_default_output(const char *scene_path)
{
    const char *base = strrchr(scene_path, '/');
    base = base ? base + 1 : scene_path;
    const char *dot = strrchr(base, '.');
    size_t len = dot && dot != base ? (size_t)(dot - base) : strlen(base);
    char *out = malloc(len + 5);
    if (out != NULL)
        snprintf(out, len + 5, "%.*s.png", (int)len, base);
    return out;
}
