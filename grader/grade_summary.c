/* grade_summary.c: the report's summary: a row a submission with its counts, its scenes' squares and its verdict. */
#include "grade_summary.h"

#include "grade_html.h"
#include "grade_verdict.h"

/* Counts the scenes of s whose file is byte for byte the reference's. */
static int copies(const Grading *g, const Submission *s)
{
    int n = 0;
    for (int k = 0; k < g->render_count; k++)
        n += s->results[k].copy;
    return n;
}

/* Writes the summary: how many submissions pass every scene, then a row a submission,
 * linking to its details. */
void summary_write(FILE *f, const Grading *g)
{
    int passed = 0;
    for (int i = 0; i < g->sub_count; i++)
        passed += g->subs[i].tally[TALLY_PASS] == g->render_count;
    fprintf(f, "<section id=\"summary\">\n<h2>Summary</h2>\n<p class=\"counts\">%d of %d "
               "submission%s pass every scene.</p>\n<table class=\"summary\">\n<thead><tr><th>"
               "Submission</th><th>Kind</th><th class=\"n\">Pass</th><th class=\"n\">Fail</th>"
               "<th class=\"n\">Missing</th><th class=\"n\">Error</th><th>Scenes</th><th>"
               "Verdict</th></tr></thead>\n<tbody>\n",
            passed, g->sub_count, html_plural(g->sub_count));
    for (int i = 0; i < g->sub_count; i++) {
        const Submission *s = &g->subs[i];
        fprintf(f, "<tr><td><a href=\"#s%d\">%s</a></td><td>%s</td>", i + 1,
                html_escape(s->name), s->program ? "program" : "images");
        for (int t = 0; t < TALLY_COUNT; t++)
            fprintf(f, "<td class=\"n%s\">%d</td>", s->tally[t] == 0 ? " zero" : "", s->tally[t]);
        /* A square a scene, in its verdict's colour, named when pointed at. */
        fputs("<td class=\"dots\">", f);
        for (int k = 0; k < g->render_count; k++) {
            const VerdictInfo *v = &verdict_info[s->results[k].verdict];
            fprintf(f, "<span class=\"dot %s\" title=\"%s: %s\"></span>",
                    html_tally_class[v->tally], html_escape(g->renders[k].name), v->name);
        }
        fprintf(f, "</td><td>%s%s</td></tr>\n", html_badge(g, s, -1),
                html_copy_flag(copies(g, s)));
    }
    fputs("</tbody>\n</table>\n</section>\n", f);
}
