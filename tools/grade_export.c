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
 * the file or the command to look at; "" for a pass. */
static char *advice(const Grading *g, const Render *r, const SceneResult *res)
{
    switch (res->verdict) {
    case VERDICT_PASS: return "";
    case VERDICT_FAIL:
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
        return "Run the command below from the top of your folder, after make, and read what "
               "it prints: it ended with a failure and wrote no image.";
    case VERDICT_CRASHED:
        return "Run the command below from the top of your folder after `make SANITIZE=1`: "
               "the sanitizer names the line that crashes (or run it under gdb --args).";
    case VERDICT_TIMEOUT:
        return grade_format("Run the command below and time it: it may take %g s here. Look "
                            "for a loop that never ends, such as rays reflected with no depth "
                            "limit.",
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
 * cases stand alone). */
static char *scene_text(const Grading *g, const Submission *s, int k, bool build)
{
    const Render *r = &g->renders[k];
    const SceneResult *res = &s->results[k];
    const char *todo = advice(g, r, res);
    bool ran = res->command != NULL;
    bool show_log = ran && verdict_info[res->verdict].tally >= TALLY_MISSING;
    /* The command that renders the scene, for a scene run or an image to make again. */
    bool command = ran || (res->verdict != VERDICT_PASS && res->verdict != VERDICT_BUILD_FAILED);
    build = build && s->build_message != NULL && s->build_log_tail != NULL;
    return grade_format(
        "%s: %s.\n%s%s%s%s%s%s%s%s%s%s", verdict_info[res->verdict].name, res->message,
        figures_text(res), res->seconds > 0 ? grade_format("It ran %.2f s.\n", res->seconds) : "",
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

/* Returns the summary of the one submission of --self that Gradescope shows above the
 * tests: the score, and what went wrong before any scene (the build, with make's last
 * output; a folder with no Makefile and no image), or how the scenes were run. */
static char *summary(const Grading *g, const Submission *s)
{
    double max, got = part_points(g, s, &max);
    char *head = grade_format("Part %s: %d of %d scene%s pass: %g of %g points.\n\n%s", g->part,
                              s->tally[TALLY_PASS], g->render_count, plural(g->render_count),
                              got, max,
                              s->removed == NULL
                                  ? ""
                                  : grade_format("The submission carried build outputs, "
                                                 "removed before make so that raytra is built "
                                                 "from its sources:\n%s\n\n",
                                                 s->removed));
    if (s->build_message != NULL)
        return grade_format("%sThe build failed: %s. No scene could be run.\nRun make in a "
                            "fresh copy of what you handed in and mend the first error it "
                            "prints.\n\nThe end of make's output:\n%s\n",
                            head, s->build_message,
                            s->build_log_tail != NULL ? s->build_log_tail : "(nothing)");
    if (!s->program && s->tally[TALLY_MISSING] == g->render_count)
        return grade_format("%sThe submission has no Makefile at its top, so it was graded as "
                            "a folder of images, and it holds none. Hand in your starter's "
                            "folder as it is, with its Makefile at the top: make must build "
                            "raytra there.\n",
                            head);
    return grade_format(
        "%s%sEach test is a scene: %s compared with the reference. A pixel differs when one of "
        "its channels differs by more than %s; an image passes when at most the fraction %s "
        "of its pixels differ. Limits: %g s a scene, %g s to build, %s of address space.\n",
        head, s->program ? "Your folder was copied and built with make. " : "",
        s->program ? "raytra rendered it as the test's command shows (with the scene's "
                     "absolute path here), and its image was"
                   : "the image of its name in your folder was",
        g->threshold, g->allow, g->time_limit, g->build_time_limit,
        grade_size_text(g->memory_limit));
}

/* Writes results.json for the one submission of --self: the score, each scene that passes
 * worth its points (grading.conf, scaled to the part's); the summary; the time it took; a
 * test a scene with its points, visibility, time, verdict, figures and what to do. */
static void write_results(FILE *f, const Grading *g)
{
    const Submission *s = &g->subs[0];
    double max, got = part_points(g, s, &max), all = 0;
    for (int k = 0; k < g->render_count; k++)
        all += g->renders[k].points;
    double scale = max > 0 && all > 0 ? max / all : 1;
    fprintf(f, "{\n  \"score\": %.6g,\n  \"execution_time\": %.3f,\n  \"output\": ", got,
            clock_now() - g->began);
    put_json(f, summary(g, s));
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
                "\"%s\",\n      \"execution_time\": %.3f,\n      \"output\": ",
                pass ? r->points * scale : 0, r->points * scale, pass ? "passed" : "failed",
                s->results[k].seconds);
        put_json(f, scene_text(g, s, k, false));
        fputs(",\n      \"output_format\": \"text\",\n      \"visibility\": ", f);
        put_json(f, r->visibility);
        fputs("\n    }", f);
    }
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
