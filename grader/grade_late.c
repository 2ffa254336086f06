/* grade_late.c: late work: grading.conf's lines of it and --due, --late-until, --submitted-at read; what lateness costs a submission, in figures and in words. */
#include "grade_late.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "grade_base.h"
#include "grade_part.h"
#include "grade_time.h"

/* grading.conf's words of late work, in the order of the bits of late_conf_line's `seen`. */
enum { KEY_DUE, KEY_GRACE, KEY_PER_DAY, KEY_CAP, KEY_MAX_DAYS, KEY_UNTIL, KEY_COUNT };
static const char *const keys[KEY_COUNT][2] = {
    {"due", "TIME"},
    {"grace", "DURATION"},
    {"penalty_per_day", "PERCENT"},
    {"max_penalty", "PERCENT"},
    {"max_late_days", "DAYS"},
    {"late_until", "TIME"},
};

/* Reads a percentage, from 0 to 100, with or without its '%', into *v; false when the
 * word is none. */
static bool read_percent(const char *word, double *v)
{
    char *end;
    *v = strtod(word, &end);
    return end != word && (*end == '\0' || (end[0] == '%' && end[1] == '\0')) && *v >= 0 &&
           *v <= 100;
}

/* Reads a whole number of days, from 0 to 3650, into *v; false when the word is none. */
static bool read_days(const char *word, double *v)
{
    *v = strtod(word, NULL);
    return word[0] != '\0' && strspn(word, "0123456789") == strlen(word) && *v <= 3650;
}

/* Checks that the end of late work is not before the due date, when both are set; false
 * (reported, after `where`) when it is. */
static bool check_order(const LatePolicy *p, const char *where)
{
    return !p->due_set || !p->until_set || p->until >= p->due ||
           grade_fail("%s: the end of late work (late_until, %s) is before the due date (%s)",
                      where, time_format(p->until, p->zone), time_format(p->due, p->zone));
}

/* Reads a grading.conf line of late work, words[0..n), into g->late: "due TIME", "grace
 * DURATION", "penalty_per_day PERCENT", "max_penalty PERCENT", "max_late_days DAYS" or
 * "late_until TIME", each once (the bits of *seen). Returns false when the line is none of
 * these; else sets *ok, false (reported as `where`: what is wrong) when the line is not
 * right. */
bool late_conf_line(Grading *g, char **words, int n, const char *where, unsigned *seen, bool *ok)
{
    LatePolicy *p = &g->late;
    int k = 0, zone = 0;
    while (k < KEY_COUNT && strcmp(words[0], keys[k][0]) != 0)
        k++;
    if (k == KEY_COUNT)
        return false;
    const char *v = n == 2 ? words[1] : "";
    double x;
    if (n != 2 || (*seen & 1u << k) != 0)
        *ok = grade_fail("%s: expected '%s %s', once", where, keys[k][0], keys[k][1]);
    else if ((k == KEY_DUE || k == KEY_UNTIL) && !time_parse(v, &x, &zone))
        *ok = grade_fail("%s: '%s' is not " TIME_FORMAT_TEXT, where, v);
    else if (k == KEY_GRACE && !time_parse_duration(v, &p->grace))
        *ok = grade_fail("%s: '%s' is not a duration: 0, or a number followed by s, m, h or d "
                         "(15m, 2h, 1d)", where, v);
    else if ((k == KEY_PER_DAY || k == KEY_CAP) && !read_percent(v, &x))
        *ok = grade_fail("%s: '%s' is not a percentage of the points, from 0 to 100 (10%%)",
                         where, v);
    else if (k == KEY_MAX_DAYS && !read_days(v, &x))
        *ok = grade_fail("%s: '%s' is not a whole number of days, from 0 to 3650", where, v);
    else {
        *ok = true;
        if (k == KEY_DUE)
            p->due_set = true, p->due = x, p->zone = zone;
        else if (k == KEY_UNTIL)
            p->until_set = true, p->until = x, p->zone = p->due_set ? p->zone : zone;
        else if (k == KEY_PER_DAY)
            p->per_day = x;
        else if (k == KEY_CAP)
            p->cap_set = true, p->cap = x;
        else if (k == KEY_MAX_DAYS)
            p->max_days_set = true, p->max_days = (int)x;
        *ok = check_order(p, where);
    }
    *seen |= 1u << k;
    return true;
}

/* Reads --due and --late-until, which replace grading.conf's due and late_until (on
 * Gradescope, the assignment's dates, a student's extension's), and checks --submitted-at;
 * false (reported) when one is not right. */
bool late_read_options(Grading *g)
{
    LatePolicy *p = &g->late;
    double when;
    int zone = 0;
    const char *bad = g->due_given != NULL && !time_parse(g->due_given, &p->due, &p->zone)
                          ? "due"
                      : g->until_given != NULL && !time_parse(g->until_given, &p->until, &zone)
                          ? "late-until"
                      : g->submitted_at != NULL && !time_parse(g->submitted_at, &when, &zone)
                          ? "submitted-at"
                          : NULL;
    if (bad != NULL)
        return grade_fail("--%s takes " TIME_FORMAT_TEXT ", got '%s'", bad,
                          *bad == 'd'   ? g->due_given
                          : *bad == 'l' ? g->until_given
                                        : g->submitted_at);
    if (g->submitted_at != NULL && !g->self)
        return grade_fail("--submitted-at goes with --self: it is when the one submission "
                          "graded was handed in");
    p->due_set |= g->due_given != NULL;
    p->until_set |= g->until_given != NULL;
    if (g->until_given != NULL && !p->due_set)
        p->zone = zone;
    return check_order(p, "--due and --late-until");
}

/* Returns what lateness costs submission s: its days late, counted from the end of the
 * grace and rounded up; the penalty, per_day a day up to the cap, or all its points past
 * max_late_days or late_until; its points before and after. Nothing is counted without a
 * due date, or for a submission whose time is not known. */
Lateness late_of(const Grading *g, const Submission *s)
{
    const LatePolicy *p = &g->late;
    Lateness l = {0};
    l.points = part_points(g, s, &l.max);
    l.final = l.points;
    if (!p->due_set || s->time_source == NULL)
        return l;
    l.known = true;
    l.after = s->submitted - p->due;
    double past = l.after - p->grace;
    l.days = past <= 0 ? 0 : past >= 3650.0 * 86400 ? 3650 : (int)ceil(past / 86400);
    l.zero = (p->max_days_set && l.days > p->max_days) || (p->until_set && s->submitted > p->until);
    l.penalty = l.zero ? 100 : fmin(fmin(l.days * p->per_day, p->cap_set ? p->cap : 100), 100);
    l.final = l.points * (1 - l.penalty / 100);
    return l;
}

/* Returns where a submission's time came from, in words: its last git commit, its newest
 * file, or the time given (--submitted-at, Gradescope's). */
const char *late_source_text(const char *source)
{
    return source == NULL             ? "not known"
           : strcmp(source, "git") == 0 ? "its last git commit"
           : strcmp(source, "files") == 0 ? "the time of its newest file"
                                          : "the time given with --submitted-at";
}

/* Returns, in a sentence, when submission s was handed in and what lateness costs it; NULL
 * when no due date is set. */
char *late_describe(const Grading *g, const Submission *s)
{
    const LatePolicy *p = &g->late;
    Lateness l = late_of(g, s);
    if (!p->due_set)
        return NULL;
    if (!l.known)
        return grade_format("When it was handed in is not known (no git commit, no file): "
                            "it is not counted late (due %s).", time_format(p->due, p->zone));
    char *when = grade_format("Handed in %s (%s)", time_format(s->submitted, p->zone),
                              late_source_text(s->time_source));
    char *due = time_format(p->due, p->zone);
    char *grace = p->grace > 0 ? grade_format(", a grace of %s", time_duration_text(p->grace))
                               : "";
    if (l.after <= 0)
        return grade_format("%s, before the due date, %s: on time.", when, due);
    if (l.days == 0 && !l.zero)
        return grade_format("%s, %s after the due date, %s, within the grace of %s: on time.",
                            when, time_duration_text(60 * ceil(l.after / 60)), due,
                            time_duration_text(p->grace));
    char *late = grade_format("%s, %d day%s late (due %s%s)", when, l.days,
                              l.days == 1 ? "" : "s", due, grace);
    if (l.zero)
        return grade_format("%s: %s, the work gets 0 (%.2f of %.2f points before).", late,
                            p->until_set && s->submitted > p->until
                                ? grade_format("after the end of late work, %s",
                                               time_format(p->until, p->zone))
                                : grade_format("more than the %d day%s late work is taken",
                                               p->max_days, p->max_days == 1 ? "" : "s"),
                            l.points, l.max);
    return grade_format("%s: a penalty of %g%% of its points: %.2f of %.2f points become %.2f.",
                        late, l.penalty, l.points, l.max, l.final);
}
