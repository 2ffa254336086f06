/* grade_csv.c: grades.csv, a line a submission and scene, safe to open in a spreadsheet. */
#include "grade.h"

#include <math.h>
#include <string.h>

/* Writes text as one CSV field and a comma: quoted, its quotes doubled (RFC 4180), when it
 * holds a comma, a quote or a line break, or starts or ends with a space. A text that a
 * spreadsheet would take for a formula, starting with =, +, -, @, a tab or a carriage
 * return, gets a quote ' first, and quotes around. */
static void csv_field(FILE *f, const char *text)
{
    size_t len = strlen(text);
    bool formula = len > 0 && strchr("=+-@\t\r", text[0]) != NULL;
    bool quote = formula || strpbrk(text, ",\"\r\n") != NULL ||
                 (len > 0 && (text[0] == ' ' || text[len - 1] == ' '));
    fputs(formula ? "\"'" : quote ? "\"" : "", f);
    for (const char *p = text; *p != '\0'; p++) {
        if (*p == '"')
            fputc('"', f);
        fputc(*p, f);
    }
    fputs(quote ? "\"," : ",", f);
}

/* Writes the CSV: a header line, then one line a submission and scene; the figures, which
 * need no quoting, are empty when no comparison was made. */
void csv_write(FILE *f, const Grading *g)
{
    fputs("submission,scene,verdict,max_diff_r,max_diff_g,max_diff_b,mean_abs_diff,rmse,"
          "psnr_db,differing_pixels,differing_fraction,bbox,message,seconds\n", f);
    for (int i = 0; i < g->sub_count; i++)
        for (int k = 0; k < g->render_count; k++) {
            const SceneResult *res = &g->subs[i].results[k];
            const Figures *fig = &res->figures;
            csv_field(f, g->subs[i].name);
            csv_field(f, g->renders[k].name);
            csv_field(f, verdict_info[res->verdict].name);
            if (res->compared)
                fprintf(f, "%.6g,%.6g,%.6g,%.6g,%.6g,%s,%ld,%.6g,", fig->max[0], fig->max[1],
                        fig->max[2], fig->mean, fig->rmse,
                        isinf(fig->psnr) ? "inf" : grade_format("%.2f", fig->psnr), fig->differing,
                        fig->pixels > 0 ? (double)fig->differing / fig->pixels : 0.0);
            else
                fputs(",,,,,,,,", f);
            if (res->compared && fig->has_box)
                fprintf(f, "\"(%d,%d)-(%d,%d)\"", fig->box[0], fig->box[1], fig->box[2],
                        fig->box[3]);
            fputc(',', f);
            csv_field(f, res->message);
            if (res->seconds >= 0)
                fprintf(f, "%.3f", res->seconds);
            fputc('\n', f);
        }
}
