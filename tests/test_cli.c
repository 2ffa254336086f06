/* test_cli.c: the shared command line: positional arguments, options, a part's own, errors. */
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include <unistd.h>

#include "cli.h"
#include "part_options.h"
#include "testing.h"

static const CliSpec spec = {"1.4-bvh", "testing", NULL};
static const CliSpec first_part = {"1.1-spheres-red", "testing", NULL};
static const CliSpec sampling_part = {"1.6-monte-carlo", "testing", NULL};

/* Returns part's spec with the tables of options the part declares. */
static CliSpec with_options(const CliSpec *part)
{
    CliSpec s = *part;
    s.options = part_options_of(part->part);
    return s;
}

/* Parses the words of a command line (ended by NULL) into opts. */
static CliResult parse_words(const CliSpec *part, Options *opts, va_list ap)
{
    char *argv[32] = {"raytra"};
    int argc = 1;
    for (char *a; (a = va_arg(ap, char *)) != NULL;)
        argv[argc++] = a;
    CliSpec s = with_options(part);
    return cli_parse(&s, argc, argv, opts);
}

/* Parses the words of a command line (ended by NULL) into opts. What cli_parse prints
 * (the refusals these tests provoke) is shown labelled, so that a passing run does not
 * look like one that failed. */
static CliResult parse_as(const CliSpec *part, Options *opts, va_list ap)
{
    fflush(stderr);
    int saved = dup(STDERR_FILENO);
    FILE *caught = tmpfile();
    ck_assert(saved >= 0 && caught != NULL);
    ck_assert_int_ge(dup2(fileno(caught), STDERR_FILENO), 0);
    CliResult r = parse_words(part, opts, ap);
    fflush(stderr);
    dup2(saved, STDERR_FILENO);
    close(saved);
    rewind(caught);
    char line[512];
    while (fgets(line, sizeof line, caught) != NULL)
        fprintf(stderr, "test_cli: refused, as it should be: %s", line);
    fclose(caught);
    return r;
}

/* Parses the words of a command line (ended by NULL) as part 1.1 does. */
static CliResult parse_first(Options *opts, ...)
{
    va_list ap;
    va_start(ap, opts);
    CliResult r = parse_as(&first_part, opts, ap);
    va_end(ap);
    return r;
}

/* Parses the words of a command line (ended by NULL) as part 1.4 does. */
static CliResult parse(Options *opts, ...)
{
    va_list ap;
    va_start(ap, opts);
    CliResult r = parse_as(&spec, opts, ap);
    va_end(ap);
    return r;
}

/* Parses the words of a command line (ended by NULL) as part does, expecting result;
 * returns (to free) what cli_parse printed on standard error. */
static char *messages_of(const CliSpec *part, CliResult result, ...)
{
    fflush(stderr);
    int saved = dup(STDERR_FILENO);
    FILE *caught = tmpfile();
    ck_assert(saved >= 0 && caught != NULL);
    ck_assert_int_ge(dup2(fileno(caught), STDERR_FILENO), 0);
    Options opts;
    va_list ap;
    va_start(ap, result);
    CliResult got = parse_words(part, &opts, ap);
    va_end(ap);
    fflush(stderr);
    dup2(saved, STDERR_FILENO);
    close(saved);
    char *text = calloc(1, 4096);
    ck_assert_ptr_nonnull(text);
    rewind(caught);
    text[fread(text, 1, 4095, caught)] = '\0';
    fclose(caught);
    ck_assert_msg(got == result, "expected result %d, got %d; messages:\n%s", result, got, text);
    return text;
}

/* Asserts that the command line (ended by NULL) is a usage error whose message is expected. */
#define ck_assert_usage_message(part, expected, ...)                                               \
    do {                                                                                           \
        char *text_ = messages_of((part), CLI_BAD_USAGE, __VA_ARGS__, NULL);                       \
        ck_assert_str_eq(text_, expected "\n");                                                    \
        free(text_);                                                                               \
    } while (0)

START_TEST(scene_and_output)
{
    Options o;
    ck_assert_int_eq(parse(&o, "s.scn", "out.png", NULL), CLI_RUN);
    ck_assert_str_eq(o.scene, "s.scn");
    ck_assert_str_eq(o.output, "out.png");
    ck_assert_int_ge(o.threads, 1);
    ck_assert(!o.quiet && !o.linear && !o.convention_given);
    ck_assert_int_eq(o.convention, CONVENTION_LECTURE);
    ck_assert_double_eq(o.scale, 1);
    ck_assert_int_eq(cli_int(&o, "max-depth"), 20);
    ck_assert_double_eq(cli_number(&o, "ray-offset"), 0x1p-32);
    ck_assert_int_eq(cli_int(&o, "mode"), 3);
    ck_assert(!cli_flag(&o, "two-sided") && !o.strict);
}
END_TEST

START_TEST(shared_options)
{
    Options o;
    ck_assert_int_eq(parse(&o, "-j", "3", "-q", "--convention", "fall2016", "s.scn", "-oout.pfm",
                           "--scale=0.5", "--linear", NULL),
                     CLI_RUN);
    ck_assert_int_eq(o.threads, 3);
    ck_assert(o.quiet && o.linear && o.convention_given);
    ck_assert_int_eq(o.convention, CONVENTION_FALL2016);
    ck_assert_str_eq(o.output, "out.pfm");
    ck_assert_double_eq(o.scale, 0.5);
    ck_assert_int_eq(parse(&o, "--threads=2", "--output", "x.png", "--", "-odd.scn", NULL),
                     CLI_RUN);
    ck_assert_int_eq(o.threads, 2);
    ck_assert_str_eq(o.scene, "-odd.scn");
}
END_TEST

START_TEST(part_options_and_arguments)
{
    Options o;
    ck_assert_int_eq(parse(&o, "--max-depth", "5", "--two-sided", "s.scn", "o.png", "2", NULL),
                     CLI_RUN);
    ck_assert_int_eq(cli_int(&o, "max-depth"), 5);
    ck_assert(cli_flag(&o, "two-sided"));
    ck_assert_int_eq(cli_int(&o, "mode"), 2);
    ck_assert_int_eq(parse(&o, "s.scn", "--mode", "1", NULL), CLI_RUN);
    ck_assert_int_eq(cli_int(&o, "mode"), 1);
    /* Part 1.1 knows neither the options nor the argument of later parts. */
    ck_assert_int_eq(parse_first(&o, "--max-depth", "5", "s.scn", NULL), CLI_BAD_USAGE);
    ck_assert_int_eq(parse_first(&o, "s.scn", "o.png", "2", NULL), CLI_BAD_USAGE);
    ck_assert_int_eq(parse_first(&o, "s.scn", "o.png", NULL), CLI_RUN);
}
END_TEST

/* Checks the options of one part: each with its help, its placeholder when it takes a
 * value, a range that holds its fallback, and a name and a letter of its own. */
static void check_part_options(const char *part)
{
    const CliOption *const *tables = part_options_of(part);
    Options opts;
    cli_defaults(&opts, tables);
    const CliOption *every[64];
    int n = 0;
    for (const CliOption *o = cli_options; o->name != NULL; o++)
        every[n++] = o;
    for (int k = 0; k < opts.part_count; k++)
        every[n++] = opts.part_rows[k];
    every[n++] = cli_option_named(tables, "help");
    every[n++] = cli_option_named(tables, "version");
    for (int k = 0; k < n; k++) {
        const CliOption *o = every[k];
        ck_assert_msg(o->help != NULL && o->help[0] != '\0', "%s has no help", o->name);
        ck_assert_msg((o->kind == OPTION_FLAG) == (o->metavar == NULL), "%s's metavar", o->name);
        if (o->kind == OPTION_INT || o->kind == OPTION_NUMBER)
            ck_assert_msg(o->min <= o->max && (o->fallback == 0 ||
                                               (o->fallback >= o->min && o->fallback <= o->max)),
                          "%s's range", o->name);
        ck_assert_msg(o->argument == NULL || o->kind != OPTION_FLAG, "%s", o->name);
        ck_assert_ptr_eq(cli_option_named(tables, o->name), o);
        for (int j = 0; j < k; j++)
            ck_assert_msg(strcmp(every[j]->name, o->name) != 0 &&
                              (o->letter == 0 || every[j]->letter != o->letter),
                          "%s: %s and %s share a name or a letter", part, every[j]->name, o->name);
    }
    ck_assert_ptr_null(cli_option_named(tables, "nope"));
}

START_TEST(the_table_is_consistent)
{
    const char *parts[] = {"1.1-spheres-red", "1.2-shading", "1.3-shadows-mirror", "1.4-bvh",
                           "1.5-refraction", "1.6-monte-carlo"};
    for (size_t k = 0; k < sizeof parts / sizeof *parts; k++)
        check_part_options(parts[k]);
    /* Each part keeps the options of the parts before it, but 1.6 drops 1.4's MODE. */
    ck_assert_ptr_nonnull(cli_option_named(part_options_of("1.5-refraction"), "mode"));
    ck_assert_ptr_null(cli_option_named(part_options_of("1.6-monte-carlo"), "mode"));
    ck_assert_ptr_null(cli_option_named(part_options_of("1.1-spheres-red"), "two-sided"));
}
END_TEST

START_TEST(usage_errors)
{
    Options o;
    ck_assert_int_eq(parse(&o, NULL), CLI_BAD_USAGE);
    ck_assert_int_eq(parse(&o, "--nope", "s.scn", NULL), CLI_BAD_USAGE);
    ck_assert_int_eq(parse(&o, "-j", "0", "s.scn", NULL), CLI_BAD_USAGE);
    ck_assert_int_eq(parse(&o, "-j", "two", "s.scn", NULL), CLI_BAD_USAGE);
    ck_assert_int_eq(parse(&o, "s.scn", "-j", NULL), CLI_BAD_USAGE);
    ck_assert_int_eq(parse(&o, "--quiet=yes", "s.scn", NULL), CLI_BAD_USAGE);
    ck_assert_int_eq(parse(&o, "--convention", "spring", "s.scn", NULL), CLI_BAD_USAGE);
    ck_assert_int_eq(parse(&o, "--scale", "0", "s.scn", NULL), CLI_BAD_USAGE);
    ck_assert_int_eq(parse(&o, "-o", "a.png", "s.scn", "b.png", NULL), CLI_BAD_USAGE);
    ck_assert_int_eq(parse(&o, "s.scn", "o.png", "4", NULL), CLI_BAD_USAGE);
    ck_assert_int_eq(parse(&o, "s.scn", "o.png", "1", "extra", NULL), CLI_BAD_USAGE);
    /* The output twice, whichever comes first; numbers as in scene files, not hexadecimal. */
    ck_assert_int_eq(parse(&o, "s.scn", "a.png", "-o", "b.png", NULL), CLI_BAD_USAGE);
    ck_assert_int_eq(parse(&o, "--scale", "0x10", "s.scn", NULL), CLI_BAD_USAGE);
    ck_assert_int_eq(parse(&o, "--scale", "inf", "s.scn", NULL), CLI_BAD_USAGE);
    ck_assert_int_eq(parse(&o, "--mode", "0x1", "s.scn", NULL), CLI_BAD_USAGE);
    ck_assert_int_eq(parse(&o, "s.scn", "--max-depth", NULL), CLI_BAD_USAGE);
}
END_TEST

START_TEST(a_value_given_twice_is_refused)
{
    /* The output, the course's positional arguments and every option that takes a
     * value: given twice in any spelling, by position or by name, even with the same
     * value; the message shows both, in the order of the command line. */
    ck_assert_usage_message(&spec,
                            "raytra: the output is given twice ('a.png' and 'b.png'); "
                            "give it once",
                            "-o", "a.png", "s.scn", "b.png");
    ck_assert_usage_message(&spec,
                            "raytra: the output is given twice ('a.png' and 'b.png'); "
                            "give it once",
                            "s.scn", "--output=a.png", "-ob.png");
    ck_assert_usage_message(&spec,
                            "raytra: MODE (--mode) is given twice ('1' and '2'); give it once",
                            "s.scn", "a.png", "1", "--mode", "2");
    ck_assert_usage_message(&spec,
                            "raytra: MODE (--mode) is given twice ('1' and '2'); give it once",
                            "--mode", "1", "s.scn", "--mode", "2");
    ck_assert_usage_message(&spec,
                            "raytra: MODE (--mode) is given twice ('2' and '2'); give it once",
                            "--mode=2", "s.scn", "o.png", "2");
    ck_assert_usage_message(&sampling_part,
                            "raytra: P (--samples) is given twice ('3' and '4'); give it once",
                            "s.scn", "o.png", "3", "--samples", "4");
    ck_assert_usage_message(&sampling_part,
                            "raytra: S (--light-samples) is given twice ('2' and '3'); give it "
                            "once",
                            "--light-samples", "2", "s.scn", "o.png", "3", "3");
    ck_assert_usage_message(&spec, "raytra: --threads is given twice ('2' and '3'); give it once",
                            "-j2", "s.scn", "--threads", "3");
    ck_assert_usage_message(&spec,
                            "raytra: --convention is given twice ('lecture' and 'fall2016'); "
                            "give it once",
                            "--convention", "lecture", "s.scn", "--convention", "fall2016");
    ck_assert_usage_message(&spec, "raytra: --view is given twice ('id' and 'id'); give it once",
                            "--view", "id", "s.scn", "--view", "id");
    /* A flag says the same thing twice: no conflict. */
    Options o;
    ck_assert_int_eq(parse(&o, "-q", "s.scn", "-q", "--linear", "--linear", NULL), CLI_RUN);
    ck_assert(o.quiet && o.linear);
}
END_TEST

START_TEST(a_negative_number_is_a_bad_value)
{
    /* A negative P, S or MODE is told as 0 or abc is, not as an unknown option. */
    const char *words[] = {"0", "abc", "-1", "-2.5"};
    for (size_t k = 0; k < sizeof words / sizeof *words; k++) {
        char expected[128];
        char *text = messages_of(&sampling_part, CLI_BAD_USAGE, "s.scn", "o.png", words[k], NULL);
        snprintf(expected, sizeof expected,
                 "raytra: P takes a whole number from 1 to 64, got '%s'\n", words[k]);
        ck_assert_str_eq(text, expected);
        free(text);
        text = messages_of(&sampling_part, CLI_BAD_USAGE, "s.scn", "o.png", "2", words[k], NULL);
        snprintf(expected, sizeof expected,
                 "raytra: S takes a whole number from 1 to 64, got '%s'\n", words[k]);
        ck_assert_str_eq(text, expected);
        free(text);
        text = messages_of(&sampling_part, CLI_BAD_USAGE, "-j", words[k], "s.scn", NULL);
        snprintf(expected, sizeof expected,
                 "raytra: --threads takes a whole number from 1 to 256, got '%s'\n", words[k]);
        ck_assert_str_eq(text, expected);
        free(text);
    }
    ck_assert_usage_message(&spec, "raytra: MODE takes a whole number from 0 to 3, got '-1'",
                            "s.scn", "o.png", "-1");
    /* Options around them are still options; a word like an option is still refused. */
    Options o;
    ck_assert_int_eq(parse(&o, "s.scn", "-q", "o.png", "2", "--linear", NULL), CLI_RUN);
    ck_assert(o.quiet && o.linear && cli_int(&o, "mode") == 2);
    ck_assert_str_eq(o.output, "o.png");
    ck_assert_usage_message(&spec,
                            "raytra: unknown option or wrong use of '-x' (raytra --help lists "
                            "them)",
                            "s.scn", "o.png", "-x");
}
END_TEST

START_TEST(help_and_version)
{
    Options o;
    ck_assert_ptr_nonnull(freopen("/dev/null", "w", stdout));
    ck_assert_int_eq(parse(&o, "--help", NULL), CLI_DONE);
    ck_assert_int_eq(parse(&o, "s.scn", "-h", NULL), CLI_DONE);
    ck_assert_int_eq(parse(&o, "--version", NULL), CLI_DONE);
}
END_TEST

START_TEST(help_lists_every_option)
{
    char *text;
    size_t size;
    FILE *f = open_memstream(&text, &size);
    CliSpec with = with_options(&spec);
    cli_print_help(&with, f);
    fclose(f);
    const char *expected[] = {"usage: raytra SCENE [OUTPUT] [MODE] [options]",
                              "--output FILE",
                              "-j, --threads N",
                              "--convention NAME",
                              "--scale F",
                              "--linear",
                              "--max-depth N",
                              "--two-sided",
                              "--mode MODE",
                              "exit status"};
    for (size_t k = 0; k < sizeof expected / sizeof *expected; k++)
        ck_assert_msg(strstr(text, expected[k]) != NULL, "'%s' missing from:\n%s", expected[k],
                      text);
    free(text);
}
END_TEST

START_TEST(default_output)
{
    char *name = cli_default_output("scenes/spheres-three.scn");
    ck_assert_str_eq(name, "spheres-three.png");
    free(name);
    name = cli_default_output("noext");
    ck_assert_str_eq(name, "noext.png");
    free(name);
    name = cli_default_output("../a.b/.hidden");
    ck_assert_str_eq(name, ".hidden.png");
    free(name);
}
END_TEST

/* The command line's tests. */
static Suite *cli_suite(void)
{
    Suite *s = suite_create("cli");
    TCase *tc = tcase_create("cli");
    tcase_add_test(tc, scene_and_output);
    tcase_add_test(tc, shared_options);
    tcase_add_test(tc, the_table_is_consistent);
    tcase_add_test(tc, part_options_and_arguments);
    tcase_add_test(tc, usage_errors);
    tcase_add_test(tc, a_value_given_twice_is_refused);
    tcase_add_test(tc, a_negative_number_is_a_bad_value);
    tcase_add_test(tc, help_and_version);
    tcase_add_test(tc, help_lists_every_option);
    tcase_add_test(tc, default_output);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(cli_suite)
