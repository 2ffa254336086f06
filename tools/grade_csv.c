/* grade_csv.c: grades.csv, a line a submission and scene, safe to open in a spreadsheet. */
#include "grade_csv.h"

#include <math.h>
#include <string.h>

/* Writes text as one CSV field followed by end (',' or '\n'): quoted, its quotes doubled
 * (RFC 4180), when it holds a comma, a quote or a line break, or starts or ends with a
 * space. A text field (not a figure) that a spreadsheet would take for a formula, starting
 * with =, +, -, @, a tab or a carriage return, gets a quote ' first, and quotes around. */
static void csv_field(FILE *f, const char *text, bool is_text, char end)
{
    size_t len = strlen(text);
    bool formula = is_text && len > 0 && strchr("=+-@\t\r", text[0]) != NULL;
    bool quote = formula || strpbrk(text, ",\"\r\n") != NULL ||
                 (len > 0 && (text[0] == ' ' || text[len - 1] == ' '));
    if (quote) {
        fputc('"', f);
        if (formula)
            fputc('\'', f);
        for (const char *p = text; *p != '\0'; p++) {
            if (*p == '"')
                fputc('"', f);
            fputc(*p, f);
        }
        fputc('"', f);
    } else {
        fputs(text, f);
    }
    fputc(end, f);
}

/* Writes the CSV: a header line, then one line a submission and scene. */
void csv_write(FILE *f, const Grading *g)
{
    static const char *const columns[] = {
        "submission",         "scene",         "verdict", "max_diff_r", "max_diff_g",
        "max_diff_b",         "mean_abs_diff", "rmse",    "psnr_db",    "differing_pixels",
        "differing_fraction", "bbox",          "message", "seconds",
    };
    enum { COLUMNS = sizeof columns / sizeof columns[0] };
    for (int c = 0; c < COLUMNS; c++)
        csv_field(f, columns[c], true, c + 1 < COLUMNS ? ',' : '\n');
    for (int i = 0; i < g->sub_count; i++)
        for (int k = 0; k < g->render_count; k++) {
            const Submission *s = &g->subs[i];
            const SceneResult *res = &s->results[k];
            const Figures *fig = &res->figures;
            char v[COLUMNS][64] = {{0}};
            if (res->compared) {
                for (int c = 0; c < 3; c++)
                    snprintf(v[3 + c], sizeof v[0], "%.6g", fig->max[c]);
                snprintf(v[6], sizeof v[0], "%.6g", fig->mean);
                snprintf(v[7], sizeof v[0], "%.6g", fig->rmse);
                snprintf(v[8], sizeof v[0], isinf(fig->psnr) ? "inf" : "%.2f", fig->psnr);
                snprintf(v[9], sizeof v[0], "%ld", fig->differing);
                snprintf(v[10], sizeof v[0], "%.6g",
                         fig->pixels > 0 ? (double)fig->differing / fig->pixels : 0.0);
                if (fig->has_box)
                    snprintf(v[11], sizeof v[0], "(%d,%d)-(%d,%d)", fig->box[0], fig->box[1],
                             fig->box[2], fig->box[3]);
            }
            if (res->seconds >= 0)
                snprintf(v[13], sizeof v[0], "%.3f", res->seconds);
            csv_field(f, s->name, true, ',');
            csv_field(f, g->renders[k].name, true, ',');
            csv_field(f, verdict_info[res->verdict].name, true, ',');
            for (int c = 3; c <= 11; c++)
                csv_field(f, v[c], false, ',');
            csv_field(f, res->message, true, ',');
            csv_field(f, v[13], false, '\n');
        }
}
