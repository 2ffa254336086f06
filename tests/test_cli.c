/* test_cli.c: the shared command line: positional arguments, options, a part's own, errors. */
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "testing.h"

static const CliSpec spec = {"1.4-bvh", "testing"};
static const CliSpec first_part = {"1.1-spheres-red", "testing"};

/* Parses the words of a command line (ended by NULL) into opts. */
static CliResult parse_as(const CliSpec *part, Options *opts, va_list ap)
{
    char *argv[32] = {"raytra"};
    int argc = 1;
    for (char *a; (a = va_arg(ap, char *)) != NULL;)
        argv[argc++] = a;
    return cli_parse(part, argc, argv, opts);
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
    ck_assert_int_eq(o.max_depth, 20);
    ck_assert_double_eq(o.ray_offset, 0x1p-32);
    ck_assert_int_eq(o.mode, 3);
    ck_assert(!o.two_sided && !o.strict);
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
    ck_assert_int_eq(o.max_depth, 5);
    ck_assert(o.two_sided);
    ck_assert_int_eq(o.mode, 2);
    ck_assert_int_eq(parse(&o, "s.scn", "--mode", "1", NULL), CLI_RUN);
    ck_assert_int_eq(o.mode, 1);
    /* Part 1.1 knows neither the options nor the argument of later parts. */
    ck_assert_int_eq(parse_first(&o, "--max-depth", "5", "s.scn", NULL), CLI_BAD_USAGE);
    ck_assert_int_eq(parse_first(&o, "s.scn", "o.png", "2", NULL), CLI_BAD_USAGE);
    ck_assert_int_eq(parse_first(&o, "s.scn", "o.png", NULL), CLI_RUN);
}
END_TEST

START_TEST(the_table_is_consistent)
{
    for (const CliOption *o = cli_options; o->name != NULL; o++) {
        ck_assert_msg(o->help != NULL && o->help[0] != '\0', "%s has no help", o->name);
        ck_assert_msg((o->kind == OPTION_FLAG) == (o->metavar == NULL), "%s's metavar", o->name);
        if (o->kind == OPTION_INT || o->kind == OPTION_NUMBER)
            ck_assert_msg(o->min <= o->max && (o->fallback == 0 || (o->fallback >= o->min &&
                                                                    o->fallback <= o->max)),
                          "%s's range", o->name);
        ck_assert_msg(o->argument == NULL || o->kind != OPTION_FLAG, "%s", o->name);
        ck_assert_msg(o->last_part == 0 || o->last_part >= o->first_part, "%s", o->name);
        ck_assert_ptr_eq(cli_option_named(o->name), o);
        for (const CliOption *p = cli_options; p < o; p++)
            ck_assert_msg(p->field != o->field && (o->letter == 0 || p->letter != o->letter),
                          "%s and %s share a field or a letter", p->name, o->name);
    }
    ck_assert_int_eq(cli_part_number("1.4-bvh"), 14);
    ck_assert_ptr_null(cli_option_named("nope"));
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
    cli_print_help(&spec, f);
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
    tcase_add_test(tc, help_and_version);
    tcase_add_test(tc, help_lists_every_option);
    tcase_add_test(tc, default_output);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(cli_suite)
