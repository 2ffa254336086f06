/* grade_gradescope.c: Gradescope's results.json for the one submission of --self: its score, summary and tests. */
#include "grade_gradescope.h"

#include <string.h>

#include "grade_base.h"
#include "grade_feedback.h"
#include "grade_late.h"
#include "grade_report.h"
#include "grade_time.h"
#include "grade_utf8.h"
#include "progress.h"

/* Writes text as a JSON string, in quotes: the quote, the backslash and each control
 * character escaped, each byte of no valid UTF-8 character made U+FFFD (JSON is UTF-8). */
static void put_json(FILE *f, const char *text)
{
    fputc('"', f);
    for (const char *t = text; *t != '\0';) {
        unsigned long c = 0;
        int n = utf8_read(t, &c);
        if (n == 0)
            fputs("\\ufffd", f);
        else if (c == '"' || c == '\\')
            fprintf(f, "\\%c", (int)c);
        else if (c == '\n')
            fputs("\\n", f);
        else if (c < 0x20)
            fprintf(f, "\\u%04lx", c);
        else
            fwrite(t, 1, (size_t)n, f);
        t += n > 0 ? n : 1;
    }
    fputc('"', f);
}

/* Returns "s" for a count other than 1, the plural's ending. */
static const char *plural(int n)
{
    return n == 1 ? "" : "s";
}

/* Tells whether Gradescope shows render r's test to students whenever it shows the results:
 * its visibility is "visible" (grading.conf's default). */
static bool shown(const Render *r)
{
    return strcmp(r->visibility, "visible") == 0;
}

/* Tells whether results.json carries the note that keeps the total hidden: a scene that
 * counts (points above 0) is "hidden", which, Gradescope's specification once said, does
 * not hide the total as a test shown later (after_due_date, after_published) does. */
static bool needs_total_note(const Grading *g)
{
    for (int k = 0; k < g->render_count; k++)
        if (strcmp(g->renders[k].visibility, "hidden") == 0 && g->renders[k].points > 0)
            return true;
    return false;
}

/* Returns points as the summary gives them: at most two decimals, no trailing zeros. */
static char *points_text(double points)
{
    char *text = grade_format("%.2f", points);
    char *end = text + strlen(text);
    while (end[-1] == '0')
        *--end = '\0';
    if (end[-1] == '.')
        end[-1] = '\0';
    return text;
}

/* Returns, for the student, when submission s was handed in and what lateness costs it,
 * its final score too unless the total is shown later; "" without a due date. */
static char *late_text(const Grading *g, const Submission *s, bool total_later)
{
    const LatePolicy *p = &g->late;
    Lateness l = late_of(g, s);
    if (!l.known)
        return "";
    char *when = grade_format("Handed in %s", time_format(s->submitted, p->zone));
    char *due = time_format(p->due, p->zone);
    if (l.days == 0 && !l.zero)
        return grade_format("%s: on time (due %s).\n\n", when, due);
    char *late = grade_format("%s, %d day%s late (due %s%s)", when, l.days, plural(l.days), due,
                              p->grace > 0 ? grade_format(", a grace of %s",
                                                          time_duration_text(p->grace))
                                           : "");
    char *score = total_later ? "" : grade_format(" Your score: %s of %s points.",
                                                  points_text(l.final), points_text(l.max));
    if (l.zero)
        return grade_format("%s: later than late work is taken, so the work gets 0.%s\n\n", late,
                            score);
    return grade_format("%s: the late penalty takes %s%% of your points.%s\n\n", late,
                        points_text(l.penalty), score);
}

/* Returns the summary of the one submission of --self that Gradescope shows above the
 * tests, to students whenever it shows the results: the score of the scenes whose tests
 * are shown (visible) alone, the others neither counted nor named, and whether the total
 * is to come; what went wrong before any scene (the build, with make's last output;
 * a folder with no Makefile and no image), or how the scenes were run; and for the
 * instructor the containment the grader ran the program in (Grading.sandbox). */
static char *summary(const Grading *g, const Submission *s, double scale)
{
    int scenes = 0, passed = 0;
    double got = 0, max = 0;
    bool all_shown = true, total_later = needs_total_note(g);
    for (int k = 0; k < g->render_count; k++) {
        const Render *r = &g->renders[k];
        bool pass = s->results[k].verdict == VERDICT_PASS;
        if (!shown(r)) {
            all_shown = false;
            total_later |= strcmp(r->visibility, "hidden") != 0;
            continue;
        }
        scenes++;
        passed += pass;
        max += r->points * scale;
        got += pass ? r->points * scale : 0;
    }
    char *score = scenes == 0 && !all_shown
                      ? "no scene's test is shown here yet."
                      : grade_format("%d of %d scene%s%s pass: %s of %s points.", passed, scenes,
                                     plural(scenes), all_shown ? "" : " shown here",
                                     points_text(got), points_text(max));
    if (total_later)
        score = grade_format("%s Gradescope shows your total score later.", score);
    char *head = grade_format("Part %s: %s\n\n%s%s", g->part, score, late_text(g, s, total_later),
                              s->removed == NULL
                                  ? ""
                                  : grade_format("The submission carried build outputs, "
                                                 "removed before make so that raytra is built "
                                                 "from its sources:\n%s\n\n",
                                                 s->removed));
    const char *sandbox = g->sandbox != NULL ? grade_format("\nSandbox: %s\n", g->sandbox) : "";
    if (s->build_message != NULL)
        return grade_format("%sThe build failed: %s. No scene could be run.\nRun make in a "
                            "fresh copy of what you handed in and mend the first error it "
                            "prints.\n\nThe end of make's output:\n%s\n%s",
                            head, s->build_message,
                            s->build_log_tail != NULL ? s->build_log_tail : "(nothing)", sandbox);
    if (!s->program && s->tally[TALLY_MISSING] == g->render_count)
        return grade_format("%sThe submission has no Makefile at its top, so it was graded as "
                            "a folder of images, and it holds none. Hand in your starter's "
                            "folder as it is, with its Makefile at the top: make must build "
                            "raytra there.\n%s",
                            head, sandbox);
    return grade_format(
        "%s%sEach test is a scene: %s compared with the reference. A pixel differs when one of "
        "its channels differs by more than %s; an image passes when at most the fraction %s "
        "of its pixels differ. Limits: %g s a scene, %g s to build, %s of address space.\n%s",
        head, s->program ? "Your folder was copied and built with make. " : "",
        s->program ? "raytra rendered it as the test's command shows (with the scene's "
                     "absolute path here), and its image was"
                   : "the image of its name in your folder was",
        g->threshold, g->allow, g->time_limit, g->build_time_limit,
        grade_size_text(g->memory_limit), sandbox);
}

/* Writes results.json for the one submission of --self, as Gradescope's autograder
 * specification has it (docs/grading.md, section 7): the score, each scene that passes
 * worth its points (grading.conf, scaled to the part's), less the late penalty (its
 * tests keep their points: the top-level score is the one Gradescope takes); the summary; the time the whole
 * grading took; a test a scene with its points, status, visibility and output (the
 * verdict, figures, time and what to do). Gradescope hides the total score while a test is
 * hidden; when a scene that counts is "hidden", a note shown once the grades are published
 * (after_published) makes sure of it. */
static void write_results(FILE *f, const Grading *g)
{
    const Submission *s = &g->subs[0];
    Lateness l = late_of(g, s);
    double all = 0;
    for (int k = 0; k < g->render_count; k++)
        all += g->renders[k].points;
    double scale = l.max > 0 && all > 0 ? l.max / all : 1;
    fprintf(f, "{\n  \"score\": %.6g,\n  \"execution_time\": %.3f,\n  \"output\": ", l.final,
            clock_now() - g->began);
    put_json(f, summary(g, s, scale));
    fputs(",\n  \"output_format\": \"text\",\n  \"visibility\": \"visible\",\n"
          "  \"stdout_visibility\": \"hidden\",\n  \"tests\": [",
          f);
    for (int k = 0; k < g->render_count; k++) {
        const Render *r = &g->renders[k];
        bool pass = s->results[k].verdict == VERDICT_PASS;
        fprintf(f, "%s\n    {\n      \"name\": ", k > 0 ? "," : "");
        put_json(f, grade_format("%s (%s)", r->name, r->scene));
        fprintf(f,
                ",\n      \"score\": %.6g,\n      \"max_score\": %.6g,\n      \"status\": "
                "\"%s\",\n      \"output\": ",
                pass ? r->points * scale : 0, r->points * scale, pass ? "passed" : "failed");
        put_json(f, feedback_text(g, s, k, false));
        fputs(",\n      \"output_format\": \"text\",\n      \"visibility\": ", f);
        put_json(f, r->visibility);
        fputs("\n    }", f);
    }
    if (needs_total_note(g))
        fprintf(f,
                "%s\n    {\n      \"name\": \"Scenes not shown\",\n      \"status\": "
                "\"passed\",\n      \"output\": \"Your total score counts scenes of your "
                "instructor's that are not shown to you. This note was hidden until the "
                "grades were published, which kept your total score hidden until then.\\n\",\n"
                "      \"output_format\": \"text\",\n      \"visibility\": "
                "\"after_published\"\n    }",
                g->render_count > 0 ? "," : "");
    fputs("\n  ]\n}\n", f);
}

/* Writes Gradescope's results.json for the one submission of --self to path; false
 * (reported) when it cannot. */
bool gradescope_export(const Grading *g, const char *path)
{
    if (!g->self || g->sub_count != 1)
        return grade_fail("--gradescope writes the results of one submission: use it with --self");
    return report_write_whole(path, g, write_results);
}
