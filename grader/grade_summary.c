/* grade_summary.c: the report's summary: a row a submission (its counts, points, lateness, squares and verdict), and how many of the class pass each scene. */
#include "grade_summary.h"

#include "grade_base.h"
#include "grade_html.h"
#include "grade_late.h"
#include "grade_verdict.h"

/* Counts the scenes of s whose file is byte for byte the reference's. */
static int copies(const Grading *g, const Submission *s)
{
    int n = 0;
    for (int k = 0; k < g->render_count; k++)
        n += s->results[k].copy;
    return n;
}

/* Writes the row of submission i: its name linking to its details, its kind, its counts,
 * its points and percent, with a due date its days late and final points, a square a scene
 * and its verdict. */
static void write_row(FILE *f, const Grading *g, int i)
{
    const Submission *s = &g->subs[i];
    Lateness l = late_of(g, s);
    fprintf(f, "<tr><td><a href=\"#s%d\">%s</a></td><td>%s</td>", i + 1, html_escape(s->name),
            s->program ? "program" : "images");
    for (int t = 0; t < TALLY_COUNT; t++)
        fprintf(f, "<td class=\"n%s\">%d</td>", s->tally[t] == 0 ? " zero" : "", s->tally[t]);
    fprintf(f, "<td class=\"n\">%.2f</td><td class=\"n\">%.0f%%</td>", l.points,
            l.max > 0 ? 100 * l.points / l.max : 0);
    if (g->late.due_set)
        fprintf(f, "<td class=\"n%s\" title=\"%s\">%s</td><td class=\"n\">%.2f</td>",
                l.days == 0 ? " zero" : "", html_escape(late_describe(g, s)),
                !l.known ? "?" : l.zero ? grade_format("%d (too late)", l.days)
                                        : grade_format("%d", l.days),
                l.final);
    /* A square a scene, in its verdict's colour, named when pointed at. */
    fputs("<td class=\"dots\">", f);
    for (int k = 0; k < g->render_count; k++) {
        const VerdictInfo *v = &verdict_info[s->results[k].verdict];
        fprintf(f, "<span class=\"dot %s\" title=\"%s: %s\"></span>", html_tally_class[v->tally],
                html_escape(g->renders[k].name), v->name);
    }
    fprintf(f, "</td><td>%s%s</td></tr>\n", html_badge(g, s, -1), html_copy_flag(copies(g, s)));
}

/* Writes how many of the class pass each scene ("passed by 17 of 20"), a row a scene. */
static void write_pass_rates(FILE *f, const Grading *g)
{
    fputs("<p class=\"counts rates\">Each scene over the class:</p>\n<table class=\"summary\">\n"
          "<thead><tr><th>Scene</th><th>Passed by</th>"
          "<th class=\"n\">Rate</th></tr></thead>\n<tbody>\n", f);
    for (int k = 0; k < g->render_count; k++) {
        int passed = 0;
        for (int i = 0; i < g->sub_count; i++)
            passed += g->subs[i].results[k].verdict == VERDICT_PASS;
        fprintf(f, "<tr><td>%s%s</td><td>passed by %d of %d</td><td class=\"n\">%.0f%%</td>"
                   "</tr>\n", html_escape(g->renders[k].name),
                g->renders[k].hidden ? " (hidden)" : "", passed, g->sub_count,
                g->sub_count > 0 ? 100.0 * passed / g->sub_count : 0);
    }
    fputs("</tbody>\n</table>\n", f);
}

/* Writes the summary: how many submissions pass every scene, then a row a submission,
 * linking to its details, and each scene's pass rate over the class. */
void summary_write(FILE *f, const Grading *g)
{
    int passed = 0;
    for (int i = 0; i < g->sub_count; i++)
        passed += g->subs[i].tally[TALLY_PASS] == g->render_count;
    fprintf(f, "<section id=\"summary\">\n<h2>Summary</h2>\n<p class=\"counts\">%d of %d "
               "submission%s pass every scene.</p>\n<table class=\"summary\">\n<thead><tr><th>"
               "Submission</th><th>Kind</th><th class=\"n\">Pass</th><th class=\"n\">Fail</th>"
               "<th class=\"n\">Missing</th><th class=\"n\">Error</th><th class=\"n\">Points"
               "</th><th class=\"n\">%%</th>%s<th>Scenes</th><th>Verdict</th></tr></thead>\n"
               "<tbody>\n",
            passed, g->sub_count, html_plural(g->sub_count),
            g->late.due_set ? "<th class=\"n\">Days late</th><th class=\"n\">Final</th>" : "");
    for (int i = 0; i < g->sub_count; i++)
        write_row(f, g, i);
    fputs("</tbody>\n</table>\n", f);
    write_pass_rates(f, g);
    fputs("</section>\n", f);
}
