/* testing.h: what every Check test program of raytra shares: its main and a few assertions. */
#ifndef RAYTRA_TESTING_H
#define RAYTRA_TESTING_H

#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Defines main: runs the suite that make_suite returns; exit status 0 when all pass. */
#define TEST_MAIN(make_suite)                                                                      \
    int main(void)                                                                                 \
    {                                                                                              \
        SRunner *runner = srunner_create(make_suite());                                            \
        srunner_run_all(runner, CK_NORMAL);                                                        \
        int failed = srunner_ntests_failed(runner);                                                \
        srunner_free(runner);                                                                      \
        return failed == 0 ? 0 : 1;                                                                \
    }

/* Asserts that vector actual and expected agree to within tol in every component. */
#define ck_assert_vec3_near(actual, expected, tol)                                                 \
    do {                                                                                           \
        Vec3 a_ = (actual), b_ = (expected);                                                       \
        ck_assert_msg(fabs(a_.x - b_.x) <= (tol) && fabs(a_.y - b_.y) <= (tol) &&                  \
                          fabs(a_.z - b_.z) <= (tol),                                              \
                      "expected (%.17g, %.17g, %.17g), got (%.17g, %.17g, %.17g)", b_.x, b_.y,     \
                      b_.z, a_.x, a_.y, a_.z);                                                     \
    } while (0)

/* Asserts that colour actual and expected agree to within tol in every component. */
#define ck_assert_color_near(actual, expected, tol)                                                \
    do {                                                                                           \
        Color a_ = (actual), b_ = (expected);                                                      \
        ck_assert_msg(fabs(a_.r - b_.r) <= (tol) && fabs(a_.g - b_.g) <= (tol) &&                  \
                          fabs(a_.b - b_.b) <= (tol),                                              \
                      "expected colour (%.17g, %.17g, %.17g), got (%.17g, %.17g, %.17g)", b_.r,    \
                      b_.g, b_.b, a_.r, a_.g, a_.b);                                               \
    } while (0)

/* Asserts that text contains expected, showing the whole text when it does not. */
#define ck_assert_contains(text, expected)                                                         \
    ck_assert_msg(strstr((text), (expected)) != NULL, "expected '%s' in:\n%s", (expected), (text))

#ifdef RAYTRA
/* Runs the part's raytra quietly with the shell words arguments; returns what it printed
 * on standard output (its first MiB), to free, and its wait status in *status. */
static inline char *testing_run(const char *arguments, int *status)
{
    char command[8192];
    snprintf(command, sizeof command, "'%s' -q %s 2>/dev/null", RAYTRA, arguments);
    FILE *p = popen(command, "r");
    ck_assert_ptr_nonnull(p);
    char *text = calloc(1, 1 << 20);
    ck_assert_ptr_nonnull(text);
    size_t used = fread(text, 1, (1 << 20) - 1, p);
    text[used] = '\0';
    *status = pclose(p);
    return text;
}
#endif

#endif
