/* grade_report.c: the self-contained report.html, and with it grades.csv and gradebook.csv, each written whole. */
#include "grade_report.h"

#include "grade_base.h"
#include "grade_csv.h"
#include "grade_gradebook.h"
#include "grade_html.h"
#include "grade_section.h"
#include "grade_summary.h"
#include "outfile.h"

/* The page's style sheet: grade_report.css, made by the build (Makefile) an array of C
 * strings, a line a string, so that no string is longer than the 4095 bytes ISO C promises. */
static const char *const style[] = {
#include "grade_style.h"
};

/* Writes the page's head, with a style rule a reference picture, each embedded once and
 * shown as a background beside every submission's image; the title block; and the
 * summary. */
static void write_heading(FILE *f, const Grading *g)
{
    int w, h, monte_carlo = 0;
    for (int k = 0; k < g->render_count; k++)
        monte_carlo += g->renders[k].statistical;
    fprintf(f, "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
               "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
               "<title>%s: grading report</title>\n<style>\n", html_escape(g->part));
    for (size_t k = 0; k < sizeof style / sizeof style[0]; k++)
        fputs(style[k], f);
    for (int k = 0; k < g->render_count; k++)
        if (html_picture_size(g->renders[k].reference_show, &w, &h)) {
            fprintf(f, ".ref%d{aspect-ratio:%d/%d;background-image:url(", k, w, h);
            html_put_picture(f, g->renders[k].reference_show);
            fputs(")}\n", f);
        }
    fprintf(f, "</style>\n</head>\n<body>\n<header class=\"page\"><div>\n<h1>Grading report: "
               "part %s</h1>\n<p class=\"meta\">%d submission%s from <code>%s</code>, %d scene%s "
               "each, graded %s.</p>\n<p class=\"meta\">%s A program gets %g s a scene and "
               "%g s to build; memory limit: %s.</p>\n",
            html_escape(g->part), g->sub_count, html_plural(g->sub_count),
            html_escape(g->submissions),
            g->render_count, html_plural(g->render_count), g->started,
            monte_carlo == g->render_count
                ? ""
                : grade_format("A pixel differs when one of its channels differs by more than "
                               "%s; an image passes when at most the fraction %s of its pixels "
                               "differ.",
                               html_escape(g->threshold), html_escape(g->allow)),
            g->time_limit, g->build_time_limit, grade_size_text(g->memory_limit));
    if (monte_carlo > 0)
        fprintf(f,
                "<p class=\"meta\">Monte Carlo renders (%d of the %d scenes) are judged by "
                "statistics against the mean and variance of 64 of raytra's renders "
                "(<code>NAME.stats.exr</code>), not by pixel tolerances: biased (a block's bias "
                "test, or the exact test of the pixels the references saw without noise) fails; "
                "so does too little noise, or more than the &ldquo;%s&rdquo; standard of soft "
                "shadows allows.</p>\n",
                monte_carlo, g->render_count,
                g->standard != NULL ? html_escape(g->standard) : "good");
    if (g->sandbox != NULL)
        fprintf(f, "<p class=\"meta\">Sandbox: %s.</p>\n", html_escape(g->sandbox));
    if (g->illustrations != NULL)
        fprintf(f, "<p class=\"meta\">Not graded (illustrations): %s.</p>\n",
                html_escape(g->illustrations));
    fputs("</div></header>\n<main>\n", f);
    summary_write(f, g);
}

/* Writes the whole page: the heading and summary, then a section a submission. */
static void write_html(FILE *f, const Grading *g)
{
    write_heading(f, g);
    for (int i = 0; i < g->sub_count; i++)
        section_write(f, g, i);
    fputs("</main>\n<footer>Written by raytra's <code>grader/grade</code> (docs/grading.md). The "
          "builds, images, logs and heat maps are in <code>work/</code> beside this report; its "
          "command lines start there.</footer>\n</body>\n</html>\n",
          f);
}

/* Writes the file at path with write, through a temporary renamed onto it so that it
 * appears only complete (outfile_commit fails on a write error too); false (reported) on
 * any failure. */
bool report_write_whole(const char *path, const Grading *g, void (*write)(FILE *, const Grading *))
{
    OutFile out;
    Error err;
    bool ok = outfile_open(&out, path, &err);
    if (ok)
        write(out.file, g);
    return (ok && outfile_commit(&out, &err)) || grade_fail("cannot write %s: %s", path, err.text);
}

/* Writes grades.csv, gradebook.csv and report.html into g->out; false (reported) when it
 * cannot. */
bool report_write(const Grading *g)
{
    char *table = grade_format("%s/grades.csv", g->out);
    char *book = grade_format("%s/gradebook.csv", g->out);
    char *page = grade_format("%s/report.html", g->out);
    if (!report_write_whole(table, g, csv_write) || !report_write_whole(book, g, gradebook_write) ||
        !report_write_whole(page, g, write_html))
        return false;
    fprintf(g->progress, "grade: wrote %s, %s and %s\n", page, table, book);
    return true;
}
