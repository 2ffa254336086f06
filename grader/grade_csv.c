/* grade_csv.c: grades.csv: a line a submission and scene, with its verdict, figures and points. */
#include "grade_csv.h"

#include <string.h>

#include "grade_base.h"
#include "grade_part.h"
#include "grade_verdict.h"

/* Returns text as a CSV field: quoted, its quotes doubled (RFC 4180), when it holds a
 * comma, a quote or a line break, or starts or ends with a space; a text that a spreadsheet
 * would take for a formula (=, +, -, @, a tab or a carriage return first) gets a quote '
 * first, and quotes around. */
char *csv_field(const char *text)
{
    size_t len = strlen(text);
    bool formula = len > 0 && strchr("=+-@\t\r", text[0]) != NULL;
    bool quote = formula || strpbrk(text, ",\"\r\n") != NULL ||
                 (len > 0 && (text[0] == ' ' || text[len - 1] == ' '));
    char *out = grade_alloc(2 * len + 4), *o = stpcpy(out, formula ? "\"'" : quote ? "\"" : "");
    for (const char *t = text; *t != '\0'; t++) {
        if (*t == '"')
            *o++ = '"';
        *o++ = *t;
    }
    strcpy(o, quote ? "\"" : "");
    return out;
}

/* Writes the CSV: a header line, then one line a submission and scene; the figures, which
 * need no quoting but the box, are empty when no comparison was made; last, the points the
 * scene earned (grading.conf's, scaled to the part's). */
void csv_write(FILE *f, const Grading *g)
{
    fputs("submission,scene,verdict,max_diff_r,max_diff_g,max_diff_b,mean_abs_diff,rmse,"
          "psnr_db,differing_pixels,differing_fraction,bbox,message,seconds,flag,points\n", f);
    double all = 0, max = 0;
    for (int k = 0; k < g->render_count; k++)
        all += g->renders[k].points;
    if (g->sub_count > 0)
        part_points(g, &g->subs[0], &max);
    double scale = all > 0 && max > 0 ? max / all : 1;
    for (int i = 0; i < g->sub_count; i++)
        for (int k = 0; k < g->render_count; k++) {
            const SceneResult *res = &g->subs[i].results[k];
            const Figures *fig = &res->figures;
            /* glibc prints an infinite PSNR as "inf" */
            char *figures = !res->compared ? ",,,,,,,,," : grade_format(
                "%.6g,%.6g,%.6g,%.6g,%.6g,%.2f,%ld,%.6g,%s,", fig->max[0], fig->max[1],
                fig->max[2], fig->mean, fig->rmse, fig->psnr, fig->differing,
                (double)fig->differing / fig->pixels,
                fig->differing == 0 ? "" : grade_format("\"(%d,%d)-(%d,%d)\"", fig->box[0],
                                                        fig->box[1], fig->box[2], fig->box[3]));
            fprintf(f, "%s,%s,%s,%s%s,%s,%s,%.6g\n", csv_field(g->subs[i].name),
                    csv_field(g->renders[k].name), verdict_info[res->verdict].name, figures,
                    csv_field(res->message), res->seconds > 0 ? grade_format("%.3f", res->seconds) : "",
                    res->copy ? "copy" : "",
                    res->verdict == VERDICT_PASS ? g->renders[k].points * scale : 0);
        }
}
