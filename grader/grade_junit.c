/* grade_junit.c: the verdicts as JUnit XML: a test suite a submission, a test case a scene. */
#include "grade_junit.h"

#include <string.h>

#include "grade_base.h"
#include "grade_feedback.h"
#include "grade_report.h"
#include "grade_section.h"
#include "grade_utf8.h"
#include "grade_verdict.h"

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
        int n = utf8_read(t, &c);
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
                "%s%s", v->tally == TALLY_PASS ? feedback_text(g, s, k, false) : "",
                res->command == NULL
                    ? ""
                    : grade_format("$ %s\n%s\n", section_command(s, res),
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
                put_xml(f, feedback_text(g, s, k, true), false);
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

/* Writes the verdicts to path as JUnit XML; false (reported) when it cannot. */
bool junit_export(const Grading *g, const char *path)
{
    return report_write_whole(path, g, write_junit);
}
