/* cli.c: parsing the shared options, a part's own options and its extra arguments. */
#include "cli.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "render.h"

/* Where the values of the shared options go while parsing. */
typedef struct {
    Options *opts;
    const char *convention;
    bool help, version;
} Shared;

/* Fills table with the shared options, bound to s; returns how many. */
static int shared_options(CliOption *table, Shared *s)
{
    Options *o = s->opts;
    const CliOption shared[] = {
        {"output", 'o', OPTION_TEXT, "FILE", "write the image to FILE (same as OUTPUT)", &o->output,
         0, 0},
        {"threads", 'j', OPTION_INT, "N", "render with N threads (default: one per core)",
         &o->threads, 1, 256},
        {"quiet", 'q', OPTION_FLAG, NULL, "no progress bar and no summary line", &o->quiet, 0, 0},
        {"check", 0, OPTION_FLAG, NULL,
         "read and check the scene, say what it holds, and exit without rendering", &o->check_only,
         0, 0},
        {"convention", 0, OPTION_TEXT, "NAME",
         "read planes and point lights by convention NAME: lecture (p.N + d = 0, "
         "no falloff; the default) or fall2016 (p.N = d, 1/r^2 falloff); "
         "overrides an 'o convention' line",
         &s->convention, 0, 0},
        {"scale", 0, OPTION_NUMBER, "F",
         "multiply the camera's pixel counts by F (0.25 for a quick look)", &o->scale, 1e-3, 64},
        {"linear", 0, OPTION_FLAG, NULL, "write PNG values linearly, without the sRGB curve",
         &o->linear, 0, 0},
        {"help", 'h', OPTION_FLAG, NULL, "show this help and exit", &s->help, 0, 0},
        {"version", 0, OPTION_FLAG, NULL, "show the version and exit", &s->version, 0, 0},
    };
    int n = (int)(sizeof shared / sizeof shared[0]);
    memcpy(table, shared, sizeof shared);
    return n;
}

/* Returns the number of entries before the empty one that ends list (0 for NULL). */
static int count_options(const CliOption *list)
{
    int n = 0;
    while (list != NULL && list[n].name != NULL)
        n++;
    return n;
}

/* Stores text as the value of option o; false (reported) when it is not a valid value. */
static bool set_value(const CliOption *o, const char *shown, const char *text)
{
    char *end;
    switch (o->kind) {
    case OPTION_FLAG: *(bool *)o->value = true; return true;
    case OPTION_TEXT: *(const char **)o->value = text; return true;
    case OPTION_INT: {
        errno = 0;
        long v = strtol(text, &end, 10);
        if (end == text || *end != '\0' || errno != 0 || v < o->min || v > o->max) {
            fprintf(stderr, "raytra: %s takes a whole number from %.0f to %.0f, got '%s'\n", shown,
                    o->min, o->max, text);
            return false;
        }
        *(int *)o->value = (int)v;
        return true;
    }
    case OPTION_NUMBER: {
        double v = strtod(text, &end);
        if (end == text || *end != '\0' || !isfinite(v) || v < o->min || v > o->max) {
            fprintf(stderr, "raytra: %s takes a number from %g to %g, got '%s'\n", shown, o->min,
                    o->max, text);
            return false;
        }
        *(double *)o->value = v;
        return true;
    }
    }
    return false;
}

/* Finds the option called by a long name (letter 0) or by a letter. */
static const CliOption *find_option(const CliOption *table, int n, const char *name, size_t len,
                                    char letter)
{
    for (int k = 0; k < n; k++) {
        const CliOption *o = &table[k];
        if (letter != 0 ? o->letter == letter
                        : strlen(o->name) == len && strncmp(o->name, name, len) == 0)
            return o;
    }
    return NULL;
}

/* Handles argv[*i], an option, taking its value from the next word when needed. */
static bool parse_option(const CliOption *table, int n, int argc, char **argv, int *i)
{
    const char *arg = argv[*i];
    const char *value = NULL;
    const CliOption *o;
    if (arg[1] == '-') {
        const char *name = arg + 2, *eq = strchr(name, '=');
        size_t len = eq ? (size_t)(eq - name) : strlen(name);
        o = find_option(table, n, name, len, 0);
        if (eq != NULL)
            value = eq + 1;
    } else {
        o = find_option(table, n, NULL, 0, arg[1]);
        if (o != NULL && arg[2] != '\0')
            value = arg + 2;
    }
    if (o == NULL) {
        fprintf(stderr, "raytra: unknown option '%s' (raytra --help lists them)\n", arg);
        return false;
    }
    if (o->kind == OPTION_FLAG) {
        if (value != NULL) {
            fprintf(stderr, "raytra: option '--%s' takes no value\n", o->name);
            return false;
        }
    } else if (value == NULL) {
        if (*i + 1 >= argc) {
            fprintf(stderr, "raytra: option '--%s' needs a value (%s)\n", o->name, o->metavar);
            return false;
        }
        value = argv[++*i];
    }
    char shown[64];
    snprintf(shown, sizeof shown, "--%s", o->name);
    return set_value(o, shown, value);
}

/* Handles a positional argument: SCENE, OUTPUT, then the part's own, in order. */
static bool parse_positional(const CliSpec *spec, Options *opts, int *count, const char *arg)
{
    int k = (*count)++;
    if (k == 0) {
        opts->scene = arg;
        return true;
    }
    if (k == 1) {
        if (opts->output != NULL) {
            fprintf(stderr, "raytra: the output is given twice ('%s' and '%s')\n", opts->output,
                    arg);
            return false;
        }
        opts->output = arg;
        return true;
    }
    if (k - 2 >= count_options(spec->arguments)) {
        fprintf(stderr, "raytra: unexpected argument '%s' (raytra --help shows the usage)\n", arg);
        return false;
    }
    const CliOption *a = &spec->arguments[k - 2];
    return set_value(a, a->name, arg);
}

/* Reads argv into opts and the part's option variables. */
CliResult cli_parse(const CliSpec *spec, int argc, char **argv, Options *opts)
{
    memset(opts, 0, sizeof *opts);
    opts->scale = 1.0;
    Shared s = {.opts = opts};
    CliOption table[64];
    int n = shared_options(table, &s);
    int own = count_options(spec->options);
    if (own > 64 - n)
        own = 64 - n;
    for (int k = 0; k < own; k++)
        table[n++] = spec->options[k];

    int positionals = 0;
    bool only_positionals = false;
    for (int i = 1; i < argc; i++) {
        const char *arg = argv[i];
        bool ok;
        if (!only_positionals && strcmp(arg, "--") == 0) {
            only_positionals = true;
            continue;
        }
        if (only_positionals || arg[0] != '-' || arg[1] == '\0')
            ok = parse_positional(spec, opts, &positionals, arg);
        else
            ok = parse_option(table, n, argc, argv, &i);
        if (!ok)
            return CLI_BAD_USAGE;
        if (s.help) {
            cli_print_help(spec, stdout);
            return CLI_DONE;
        }
        if (s.version) {
            printf("raytra %s (part %s)\n", RAYTRA_VERSION, spec->part);
            return CLI_DONE;
        }
    }
    if (opts->scene == NULL) {
        fprintf(stderr, "raytra: no scene file given\nusage: raytra SCENE [OUTPUT] [options]"
                        " (raytra --help for more)\n");
        return CLI_BAD_USAGE;
    }
    if (s.convention != NULL) {
        if (!convention_from_name(s.convention, &opts->convention)) {
            fprintf(stderr, "raytra: unknown convention '%s' (lecture or fall2016)\n",
                    s.convention);
            return CLI_BAD_USAGE;
        }
        opts->convention_given = true;
    }
    if (opts->threads == 0)
        opts->threads = render_default_threads();
    return CLI_RUN;
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

/* Prints the options of one table under a heading. */
static void print_options(FILE *f, const CliOption *table, int n)
{
    for (int k = 0; k < n; k++) {
        const CliOption *o = &table[k];
        char left[64];
        snprintf(left, sizeof left, "%c%c%c --%s%s%s", o->letter ? '-' : ' ',
                 o->letter ? o->letter : ' ', o->letter ? ',' : ' ', o->name, o->metavar ? " " : "",
                 o->metavar ? o->metavar : "");
        print_entry(f, left, o->help);
    }
}

/* Prints the usage, the arguments and every option with its help. */
void cli_print_help(const CliSpec *spec, FILE *f)
{
    fprintf(f, "usage: raytra SCENE [OUTPUT]");
    for (int k = 0; k < count_options(spec->arguments); k++)
        fprintf(f, " [%s]", spec->arguments[k].name);
    fprintf(f, " [options]\n\nraytra %s, part %s: %s\n\narguments:\n", RAYTRA_VERSION, spec->part,
            spec->purpose);
    print_entry(f, "SCENE", "the scene file to render (see docs/scene-format.md)");
    print_entry(f, "OUTPUT",
                "the image to write: .png (8-bit sRGB) or .pfm (32-bit float, linear); "
                "default: the scene's name with .png, in the working directory");
    for (int k = 0; k < count_options(spec->arguments); k++)
        print_entry(f, spec->arguments[k].name, spec->arguments[k].help);

    Options dummy;
    Shared s = {.opts = &dummy};
    CliOption table[16];
    fprintf(f, "\noptions:\n");
    print_options(f, table, shared_options(table, &s));
    if (count_options(spec->options) > 0) {
        fprintf(f, "\noptions of part %s:\n", spec->part);
        print_options(f, spec->options, count_options(spec->options));
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
