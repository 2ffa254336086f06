/* test_lex.c: numbers and lines as the scene and OBJ readers see them. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lex.h"
#include "testing.h"

/* Returns the value of a word that must be a number. */
static double number(const char *word)
{
    double v = -12345;
    ck_assert_msg(lex_number(word, &v) == NUMBER_OK, "'%s' should be a number", word);
    return v;
}

START_TEST(numbers)
{
    ck_assert_double_eq(number("1"), 1);
    ck_assert_double_eq(number("-2.5"), -2.5);
    ck_assert_double_eq(number(".5"), 0.5);
    ck_assert_double_eq(number("5."), 5);
    ck_assert_double_eq(number("+4"), 4);
    ck_assert_double_eq(number("1e3"), 1000);
    ck_assert_double_eq(number("1E-3"), 0.001);
    ck_assert_double_eq(number("-0"), 0);
    ck_assert_double_eq(number("1e12"), 1e12);
}
END_TEST

START_TEST(not_numbers)
{
    const char *malformed[] = {"abc", "1.2.3", "1e",  "1e+", "0x10",        "", "-", ".",
                               "1,5", "e5",    "--1", "1f",  "\xef\xbc\x91"};
    double v;
    for (size_t k = 0; k < sizeof malformed / sizeof *malformed; k++)
        ck_assert_msg(lex_number(malformed[k], &v) == NUMBER_MALFORMED, "'%s'", malformed[k]);
    const char *infinite[] = {"nan", "NaN", "-inf", "+Infinity", "1e400", "-1e999"};
    for (size_t k = 0; k < sizeof infinite / sizeof *infinite; k++)
        ck_assert_msg(lex_number(infinite[k], &v) == NUMBER_NOT_FINITE, "'%s'", infinite[k]);
    ck_assert_int_eq(lex_number("1e308", &v), NUMBER_TOO_LARGE);
    ck_assert_int_eq(lex_number("-1.000001e12", &v), NUMBER_TOO_LARGE);
}
END_TEST

START_TEST(words)
{
    char line[] = "  l p\t1  2 \t3\r";
    Words w;
    lex_split(line, &w);
    ck_assert_int_eq(w.count, 5);
    ck_assert_str_eq(w.word[0], "l");
    ck_assert_str_eq(w.word[1], "p");
    ck_assert_str_eq(w.word[4], "3");
    char blank[] = " \t ";
    lex_split(blank, &w);
    ck_assert_int_eq(w.count, 0);
}
END_TEST

START_TEST(many_words_are_counted_not_kept)
{
    char line[1000] = "";
    for (int k = 0; k < 100; k++)
        strcat(line, "1 ");
    Words w;
    lex_split(line, &w);
    ck_assert_int_eq(w.count, 100);
}
END_TEST

START_TEST(lines)
{
    static const char text[] = "one\r\ntwo\n\nbad\0byte\nlast";
    FILE *f = fmemopen((void *)text, sizeof text - 1, "r");
    LineReader *r = malloc(sizeof *r);
    lex_start(r, f);
    ck_assert_int_eq(lex_next_line(r), LINE_OK);
    ck_assert_str_eq(r->buf, "one");
    ck_assert_int_eq(lex_next_line(r), LINE_OK);
    ck_assert_str_eq(r->buf, "two");
    ck_assert_int_eq(lex_next_line(r), LINE_OK);
    ck_assert_str_eq(r->buf, "");
    ck_assert_int_eq(lex_next_line(r), LINE_BINARY);
    ck_assert_int_eq(r->line, 4);
    ck_assert_str_eq(lex_binary_byte_name(r), "NUL byte");
    /* The reader stops at the NUL byte itself, reading nothing after it. */
    ck_assert_int_eq(ftell(f), (long)strlen("one\r\ntwo\n\nbad") + 1);
    fclose(f);
    free(r);
}
END_TEST

START_TEST(binary_stops_at_the_first_bad_byte)
{
    /* A megabyte of zeros and no newline, as /dev/zero gives: one byte is read. */
    size_t size = 1 << 20;
    char *zeros = calloc(size, 1);
    FILE *f = fmemopen(zeros, size, "r");
    LineReader *r = malloc(sizeof *r);
    lex_start(r, f);
    ck_assert_int_eq(lex_next_line(r), LINE_BINARY);
    ck_assert_int_eq(r->line, 1);
    ck_assert_int_eq(ftell(f), 1);
    fclose(f);
    /* A control character (here BEL, as in a terminal escape) is binary too; tabs, form
     * feeds, carriage returns, ESC and Ctrl-Z are not. */
    static const char text[] = "s 1\t2\v3\f4\r\n\x1b[1m \x1a\nab\acd\n";
    f = fmemopen((void *)text, sizeof text - 1, "r");
    lex_start(r, f);
    ck_assert_int_eq(lex_next_line(r), LINE_OK);
    ck_assert_int_eq(lex_next_line(r), LINE_OK);
    ck_assert_int_eq(lex_next_line(r), LINE_BINARY);
    ck_assert_int_eq(r->line, 3);
    ck_assert_str_eq(lex_binary_byte_name(r), "control character");
    fclose(f);
    free(r);
    free(zeros);
}
END_TEST

START_TEST(long_lines_are_skipped)
{
    FILE *f = tmpfile();
    for (int k = 0; k < LEX_MAX_LINE + 10; k++)
        fputc('x', f);
    fputs("\nnext\n", f);
    rewind(f);
    LineReader *r = malloc(sizeof *r);
    lex_start(r, f);
    ck_assert_int_eq(lex_next_line(r), LINE_TOO_LONG);
    ck_assert_int_eq(lex_next_line(r), LINE_OK);
    ck_assert_str_eq(r->buf, "next");
    ck_assert_int_eq(r->line, 2);
    fclose(f);
    free(r);
}
END_TEST

/* The lexer's tests. */
static Suite *lex_suite(void)
{
    Suite *s = suite_create("lex");
    TCase *tc = tcase_create("lex");
    tcase_add_test(tc, numbers);
    tcase_add_test(tc, not_numbers);
    tcase_add_test(tc, words);
    tcase_add_test(tc, many_words_are_counted_not_kept);
    tcase_add_test(tc, lines);
    tcase_add_test(tc, binary_stops_at_the_first_bad_byte);
    tcase_add_test(tc, long_lines_are_skipped);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(lex_suite)
