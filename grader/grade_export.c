/* grade_export.c: the verdicts for other tools: JUnit XML, and Gradescope's results.json. */
#include "grade.h"

#include <math.h>
#include <string.h>

#include "progress.h"

/* Reads the UTF-8 character that starts at s: returns its length in bytes and sets *code,
 * or returns 0 for a byte that starts no valid character (a stray continuation byte, a
 * sequence cut short, an overlong form, a surrogate, a code point past U+10FFFF). */
static int utf8_char(const char *text, unsigned long *code)
{
    static const unsigned long least[] = {0, 0, 0x80, 0x800, 0x10000};
    const unsigned char *s = (const unsigned char *)text;
    int n = s[0] < 0x80   ? 1
            : s[0] < 0xC2 ? 0
            : s[0] < 0xE0 ? 2
            : s[0] < 0xF0 ? 3
            : s[0] < 0xF5 ? 4
                          : 0;
    unsigned long c = s[0] & (0x7Fu >> (n > 0 ? n - 1 : 0)); /* the lead byte's bits */
    /* A continuation byte is 10xxxxxx; the string's NUL ends a cut sequence here too. */
    for (int k = 1; k < n; k++) {
        if ((s[k] & 0xC0) != 0x80)
            return 0;
        c = c << 6 | (s[k] & 0x3F);
    }
    if (n == 0 || c < least[n] || (c >= 0xD800 && c <= 0xDFFF) || c > 0x10FFFF)
        return 0;
    *code = c;
    return n;
}

/* Writes text as XML 1.0 character data: the five specials as entities, a carriage return
 * as a character reference (a parser would make it a line feed), in an attribute's value
 * (`attribute`) a tab and a line feed too (which it would make spaces), and each byte XML
 * cannot hold (a control character, a byte of no valid UTF-8 character, U+FFFE and
 * U+FFFF) as the visible text \xNN. */
static void put_xml(FILE *f, const char *text, bool attribute)
{
    static const char specials[] = "&<>\"'\t\n\r", *const entities[] = {"&amp;",  "&lt;",   "&gt;",
                                                                        "&quot;", "&apos;", "&#9;",
                                                                        "&#10;",  "&#13;"};
    for (const char *t = text; *t != '\0';) {
        unsigned long c = 0;
        int n = utf8_char(t, &c);
        const char *special = n == 1 ? strchr(specials, *t) : NULL;
        if (special != NULL && !attribute && (*t == '\t' || *t == '\n'))
            fputc(*t, f);
        else if (special != NULL)
            fputs(entities[special - specials], f);
        else if (n == 0 || c < 0x20 || c == 0xFFFE || c == 0xFFFF)
            fprintf(f, "\\x%02X", (unsigned char)*t);
        else
            fwrite(t, 1, (size_t)n, f);
        t += n > 0 ? n : 1;
    }
}

/* Writes text as a JSON string, in quotes: the quote, the backslash and each control
 * character escaped, each byte of no valid UTF-8 character made U+FFFD (JSON is UTF-8). */
static void put_json(FILE *f, const char *text)
{
    fputc('"', f);
    for (const char *t = text; *t != '\0';) {
        unsigned long c = 0;
        int n = utf8_char(t, &c);
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

/* Returns imgdiff's figures for a scene, in a sentence, as the report gives them: "" when
 * no comparison was made. */
static char *figures_text(const SceneResult *res)
{
    const Figures *f = &res->figures;
    if (!res->compared)
        return "";
    return grade_format(
        "Max diff R, G, B: %.3g, %.3g, %.3g /255; mean abs diff %.3g /255; RMSE %.4g; PSNR %s; "
        "differing pixels: %ld of %ld (%.3g%%)%s.\n",
        f->max[0] * 255, f->max[1] * 255, f->max[2] * 255, f->mean * 255, f->rmse,
        isinf(f->psnr) ? "infinite (equal)" : grade_format("%.2f dB", f->psnr), f->differing,
        f->pixels, 100.0 * f->differing / (f->pixels > 0 ? (double)f->pixels : 1),
        f->differing > 0 ? grade_format(", in the box (%d,%d)-(%d,%d), y from the top", f->box[0],
                                        f->box[1], f->box[2], f->box[3])
                         : "");
}

/* Returns the command line that renders r from the top of a student's folder, as
 * the starter lays it out: ./raytra SCENE IMAGE [positional arguments]. */
static char *student_command(const Render *r)
{
    int n = 0;
    while (r->argv[RENDER_WORDS + n] != NULL)
        n++;
    char **argv = grade_alloc(((size_t)n + RENDER_WORDS + 1) * sizeof *argv);
    argv[0] = "./raytra";
    argv[1] = r->scene;
    argv[2] = r->image;
    memcpy(argv + RENDER_WORDS, r->argv + RENDER_WORDS, (size_t)n * sizeof *argv);
    return run_command_line(argv, NULL);
}

/* Returns what a student does about a scene's verdict: a sentence or two, concrete, naming
 * the file or the command to look at; "" for a pass. A hidden scene (r->hidden), which the
 * student does not have, gets advice that names no scene file and no command to run it. */
static char *advice(const Grading *g, const Render *r, const SceneResult *res)
{
    switch (res->verdict) {
    case VERDICT_PASS: return "";
    case VERDICT_FAIL:
        if (r->hidden)
            return "This scene is not in your starter, so you cannot render it yourself: run "
                   "`make check` on the starter's scenes, and look for what your program gets "
                   "right there only because of how they are arranged (the camera, the lights, "
                   "where the objects lie). Look at the box above first.";
        return grade_format("Render the scene with the command below and compare it with the "
                            "reference: `make check` in your starter writes its heat map to "
                            "out/check/%s.heat.png, black where the images agree and bright "
                            "where they differ. Look at the box above first.",
                            r->name);
    case VERDICT_WRONG_SIZE:
        return "Write the image at the size the scene file gives (its camera's width and "
               "height), whatever the options say.";
    case VERDICT_LINK:
        return "Hand in the program and let it write its images: a link is not an image.";
    case VERDICT_UNREADABLE:
        return "Write a PNG file at the path raytra gets as its second argument, with the "
               "image functions of common/ (image_write).";
    case VERDICT_MISSING:
        return "Write the image at the path raytra gets as its second argument, and hand in "
               "your folder with its Makefile at the top, as the starter has it.";
    case VERDICT_ERROR:
        if (r->hidden)
            return "Read what the program printed, below: it ended with a failure on this "
                   "scene, which is not in your starter, and wrote no image. Make sure it "
                   "reads every scene the format allows, not only the starter's.";
        return "Run the command below from the top of your folder, after make, and read what "
               "it prints: it ended with a failure and wrote no image.";
    case VERDICT_CRASHED:
        if (r->hidden)
            return "Build with `make SANITIZE=1` and run `make check`: the sanitizer names the "
                   "line that crashes. This scene is not in your starter: look for what it "
                   "may hold that the starter's scenes do not (an object, a light or a camera "
                   "placed otherwise).";
        return "Run the command below from the top of your folder after `make SANITIZE=1`: "
               "the sanitizer names the line that crashes (or run it under gdb --args).";
    case VERDICT_TIMEOUT:
        return grade_format("%s: it may take %g s here. Look for a loop that never ends, such "
                            "as rays reflected with no depth limit.",
                            r->hidden ? "Time your program on the starter's scenes (`make check`)"
                                      : "Run the command below and time it",
                            g->time_limit);
    case VERDICT_OUT_OF_MEMORY:
        return grade_format("Look for memory taken for every ray or pixel and never given "
                            "back: the program may use %s of address space here.",
                            grade_size_text(g->memory_limit));
    case VERDICT_BUILD_FAILED:
        return "Run make in a fresh copy of what you handed in and mend the first error it "
               "prints (make's last output is shown with these results).";
    default: return "";
    }
}

/* Returns the words about scene k of submission s that both formats give: the verdict and
 * its reason, the figures, the time, what to do, the command and the program's last
 * output; with `build`, make's last output too when the build failed (JUnit, whose test
 * cases stand alone). A hidden scene's words name no command that runs it: the student
 * does not have its scene file. */
static char *scene_text(const Grading *g, const Submission *s, int k, bool build)
{
    const Render *r = &g->renders[k];
    const SceneResult *res = &s->results[k];
    const char *todo = advice(g, r, res);
    bool ran = res->command != NULL;
    bool show_log = ran && verdict_info[res->verdict].tally >= TALLY_MISSING;
    /* The command that renders the scene, for a scene run or an image to make again. */
    bool command = !r->hidden &&
                   (ran || (res->verdict != VERDICT_PASS && res->verdict != VERDICT_BUILD_FAILED));
    build = build && s->build_message != NULL && s->build_log_tail != NULL;
    return grade_format(
        "%s: %s.\n%s%s%s%s%s%s%s%s%s%s", verdict_info[res->verdict].name, res->message,
        figures_text(res), res->seconds > 0 ? grade_format("Ran in %.2f s.\n", res->seconds) : "",
        todo[0] != '\0' ? grade_format("What to do: %s\n", todo) : "",
        command ? grade_format("Command (from the top of the folder): %s\n", student_command(r))
                : "",
        show_log ? "The program's last output:\n" : "",
        show_log ? (res->log_tail != NULL ? res->log_tail : "(nothing)") : "", show_log ? "\n" : "",
        build ? "The end of make's output:\n" : "", build ? s->build_log_tail : "",
        build ? "\n" : "");
}

/* Writes one test case a submission and scene, in a test suite a submission: a scene in
 * the FAIL or MISSING column a <failure>, one in the ERROR column an <error>, both typed
 * by the verdict; a pass's figures, and what the program printed, as <system-out>. */
static void write_junit(FILE *f, const Grading *g)
{
    int tally[TALLY_COUNT] = {0};
    double seconds = 0;
    for (int i = 0; i < g->sub_count; i++)
        for (int k = 0; k < g->render_count; k++) {
            tally[verdict_info[g->subs[i].results[k].verdict].tally]++;
            seconds += g->subs[i].results[k].seconds;
        }
    fputs("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"raytra grade ", f);
    put_xml(f, g->part, true);
    fprintf(f, "\" tests=\"%d\" failures=\"%d\" errors=\"%d\" time=\"%.3f\">\n",
            g->sub_count * g->render_count, tally[TALLY_FAIL] + tally[TALLY_MISSING],
            tally[TALLY_ERROR], seconds);
    for (int i = 0; i < g->sub_count; i++) {
        const Submission *s = &g->subs[i];
        seconds = 0;
        for (int k = 0; k < g->render_count; k++)
            seconds += s->results[k].seconds;
        fputs("  <testsuite name=\"", f);
        put_xml(f, s->name, true);
        fprintf(f, "\" tests=\"%d\" failures=\"%d\" errors=\"%d\" skipped=\"0\" time=\"%.3f\">\n",
                g->render_count, s->tally[TALLY_FAIL] + s->tally[TALLY_MISSING],
                s->tally[TALLY_ERROR], seconds);
        for (int k = 0; k < g->render_count; k++) {
            const SceneResult *res = &s->results[k];
            const VerdictInfo *v = &verdict_info[res->verdict];
            /* A pass says its verdict and figures in <system-out>; a run, its command
             * line and its last output. */
            char *out = grade_format(
                "%s%s", v->tally == TALLY_PASS ? scene_text(g, s, k, false) : "",
                res->command == NULL
                    ? ""
                    : grade_format("$ %s\n%s\n", report_command(s, res),
                                   res->log_tail != NULL ? res->log_tail : "(nothing)"));
            fputs("    <testcase name=\"", f);
            put_xml(f, g->renders[k].name, true);
            /* Jenkins splits a classname at its last dot into a package and a class: the
             * name's dots are written '_' here; the testsuite keeps the name as it is. */
            fputs("\" classname=\"", f);
            char *classname = grade_format("%s", s->name);
            for (char *p = strchr(classname, '.'); p != NULL; p = strchr(p, '.'))
                *p = '_';
            put_xml(f, classname, true);
            fprintf(f, "\" time=\"%.3f\">\n", res->seconds);
            if (v->tally != TALLY_PASS) {
                const char *element = v->tally == TALLY_ERROR ? "error" : "failure";
                fprintf(f, "      <%s type=\"%s\" message=\"", element, v->name);
                put_xml(f, res->message, true);
                fputs("\">", f);
                put_xml(f, scene_text(g, s, k, true), false);
                fprintf(f, "</%s>\n", element);
            }
            if (out[0] != '\0') {
                fputs("      <system-out>", f);
                put_xml(f, out, false);
                fputs("</system-out>\n", f);
            }
            fputs("    </testcase>\n", f);
        }
        fputs("  </testsuite>\n", f);
    }
    fputs("</testsuites>\n", f);
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
    char *head = grade_format("Part %s: %s\n\n%s", g->part, score,
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
 * worth its points (grading.conf, scaled to the part's); the summary; the time the whole
 * grading took; a test a scene with its points, status, visibility and output (the
 * verdict, figures, time and what to do). Gradescope hides the total score while a test is
 * hidden; when a scene that counts is "hidden", a note shown once the grades are published
 * (after_published) makes sure of it. */
static void write_results(FILE *f, const Grading *g)
{
    const Submission *s = &g->subs[0];
    double max, got = part_points(g, s, &max), all = 0;
    for (int k = 0; k < g->render_count; k++)
        all += g->renders[k].points;
    double scale = max > 0 && all > 0 ? max / all : 1;
    fprintf(f, "{\n  \"score\": %.6g,\n  \"execution_time\": %.3f,\n  \"output\": ", got,
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
        put_json(f, scene_text(g, s, k, false));
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

/* Writes the verdicts to path as JUnit XML; false (reported) when it cannot. */
bool export_junit(const Grading *g, const char *path)
{
    return report_write_whole(path, g, write_junit);
}

/* Writes Gradescope's results.json for the one submission of --self to path; false
 * (reported) when it cannot. */
bool export_gradescope(const Grading *g, const char *path)
{
    if (!g->self || g->sub_count != 1)
        return grade_fail("--gradescope writes the results of one submission: use it with --self");
    return report_write_whole(path, g, write_results);
}
