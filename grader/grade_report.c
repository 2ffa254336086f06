/* grade_report.c: the self-contained report.html, and with it grades.csv, each written whole. */
#include "grade_report.h"

#include <math.h>
#include <string.h>
#include <sys/stat.h>

#include "grade_base.h"
#include "grade_csv.h"
#include "grade_part.h"
#include "grade_run.h"
#include "grade_verdict.h"
#include "imgfile.h"
#include "outfile.h"

/* A thumbnail this narrow or narrower is shown enlarged with sharp pixels. */
#define PIXELATED_WIDTH 200

/* The largest picture embedded: thumbnails are far smaller; a larger file is a mistake. */
#define EMBED_MAX_BYTES (8L << 20)

/* The summary's class (and colour) for each tally. */
static const char *const tally_class[TALLY_COUNT] = {"pass", "fail", "missing", "error"};

/* The page's style sheet: grade_report.css, made a C string by the build (grade.mk), which
 * must stay under the 4095 bytes ISO C promises a string. */
static const char style[] =
#include "grade_style.h"
    ;

/* Returns text with the characters HTML gives a meaning written as entities: everything a
 * student named or printed goes through here. */
static char *html(const char *text)
{
    static const char specials[] = "&<>\"'", *const entities[] = {"&amp;", "&lt;", "&gt;",
                                                                  "&quot;", "&#39;"};
    char *out = grade_alloc(6 * strlen(text) + 1), *o = out;
    for (const char *t = text; *t != '\0'; t++) {
        const char *special = strchr(specials, *t);
        if (special != NULL)
            o = stpcpy(o, entities[special - specials]);
        else
            *o++ = *t;
    }
    return out;
}

/* Returns "s" for a count other than 1, the plural's ending. */
static const char *plural(int n)
{
    return n == 1 ? "" : "s";
}

/* Returns the badge of a submission's overall verdict, in its column's colour: PASS when
 * every scene passes, BUILD FAILED, or FAIL; or with k >= 0 that of scene k. */
static char *badge(const Grading *g, const Submission *s, int k)
{
    Verdict overall = s->build_message != NULL                ? VERDICT_BUILD_FAILED
                      : s->tally[TALLY_PASS] == g->render_count ? VERDICT_PASS
                                                                : VERDICT_FAIL;
    const VerdictInfo *v = &verdict_info[k >= 0 ? s->results[k].verdict : overall];
    return grade_format("<span class=\"badge %s\">%s</span>", tally_class[v->tally], v->name);
}

/* Returns the flag of a file handed in or written that is byte for byte the reference's, for
 * the instructor to look at (the verdict stays what imgdiff says): for `count` such scenes of
 * a submission, or none when count is 0. */
static char *copy_flag(int count)
{
    return count == 0 ? ""
                      : grade_format(" <span class=\"badge flag\" title=\"%d image%s byte for byte "
                                     "the reference file%s: look at how it was made\">COPY</span>",
                                     count, plural(count), plural(count));
}

/* Returns how many images of a submission are byte for byte the reference files. */
static int copies(const Grading *g, const Submission *s)
{
    int n = 0;
    for (int k = 0; k < g->render_count; k++)
        n += s->results[k].copy;
    return n;
}

/* Tells whether the thumbnail at path, made by imgdiff, can be embedded (a PNG of a sane
 * size, in pixels and in bytes), and sets its size in pixels. */
static bool picture_size(const char *path, int *width, int *height)
{
    ImgFileKind kind;
    Error err;
    struct stat st;
    return path != NULL && imgfile_header(path, &kind, width, height, &err) &&
           kind == IMGFILE_PNG && lstat(path, &st) == 0 && st.st_size <= EMBED_MAX_BYTES;
}

/* Writes the PNG at path as a data: URI, in base64. */
static void put_picture(FILE *f, const char *path)
{
    static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    FILE *in = imgfile_fopen(path);
    unsigned char d[3];
    size_t n;
    fputs("data:image/png;base64,", f);
    while (in != NULL && (n = fread(memset(d, 0, sizeof d), 1, sizeof d, in)) > 0) {
        /* Three bytes make four digits; a '=' stands for each digit of a missing byte. */
        unsigned long bits = (unsigned long)d[0] << 16 | (unsigned long)d[1] << 8 | d[2];
        for (size_t j = 0; j < 4; j++)
            fputc(j <= n ? digits[(bits >> (18 - 6 * j)) & 63] : '=', f);
    }
    if (in != NULL)
        fclose(in);
}

/* Writes the page's head, with a style rule a reference picture, each embedded once and
 * shown as a background beside every submission's image; the title block; and the
 * summary: a row a submission, linking to its details. */
static void write_heading(FILE *f, const Grading *g)
{
    int passed = 0, w, h, monte_carlo = 0;
    for (int k = 0; k < g->render_count; k++)
        monte_carlo += g->renders[k].statistical;
    fprintf(f, "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
               "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
               "<title>%s: grading report</title>\n<style>\n%s", html(g->part), style);
    for (int k = 0; k < g->render_count; k++)
        if (picture_size(g->renders[k].reference_show, &w, &h)) {
            fprintf(f, ".ref%d{aspect-ratio:%d/%d;background-image:url(", k, w, h);
            put_picture(f, g->renders[k].reference_show);
            fputs(")}\n", f);
        }
    fprintf(f, "</style>\n</head>\n<body>\n<header class=\"page\"><div>\n<h1>Grading report: "
               "part %s</h1>\n<p class=\"meta\">%d submission%s from <code>%s</code>, %d scene%s "
               "each, graded %s.</p>\n<p class=\"meta\">%s A program gets %g s a scene and "
               "%g s to build; memory limit: %s.</p>\n",
            html(g->part), g->sub_count, plural(g->sub_count), html(g->submissions),
            g->render_count, plural(g->render_count), g->started,
            monte_carlo == g->render_count
                ? ""
                : grade_format("A pixel differs when one of its channels differs by more than "
                               "%s; an image passes when at most the fraction %s of its pixels "
                               "differ.",
                               html(g->threshold), html(g->allow)),
            g->time_limit, g->build_time_limit, grade_size_text(g->memory_limit));
    if (monte_carlo > 0)
        fprintf(f,
                "<p class=\"meta\">Monte Carlo renders (%d of the %d scenes) are judged by "
                "statistics against the mean and variance of 64 of raytra's renders "
                "(<code>NAME.stats.exr</code>), not by pixel tolerances: biased (a block's bias "
                "test, or the exact test of the pixels the references saw without noise) fails; "
                "so does too little noise, or more than the &ldquo;%s&rdquo; standard of soft "
                "shadows allows.</p>\n",
                monte_carlo, g->render_count, g->standard != NULL ? html(g->standard) : "good");
    if (g->sandbox != NULL)
        fprintf(f, "<p class=\"meta\">Sandbox: %s.</p>\n", html(g->sandbox));
    if (g->illustrations != NULL)
        fprintf(f, "<p class=\"meta\">Not graded (illustrations): %s.</p>\n",
                html(g->illustrations));
    for (int i = 0; i < g->sub_count; i++)
        passed += g->subs[i].tally[TALLY_PASS] == g->render_count;
    fprintf(f, "</div></header>\n<main>\n<section id=\"summary\">\n<h2>Summary</h2>\n<p "
               "class=\"counts\">%d of %d submission%s pass every scene.</p>\n<table "
               "class=\"summary\">\n<thead><tr><th>Submission</th><th>Kind</th><th class=\"n\">"
               "Pass</th><th class=\"n\">Fail</th><th class=\"n\">Missing</th><th class=\"n\">"
               "Error</th><th>Scenes</th><th>Verdict</th></tr></thead>\n<tbody>\n",
            passed, g->sub_count, plural(g->sub_count));
    for (int i = 0; i < g->sub_count; i++) {
        const Submission *s = &g->subs[i];
        fprintf(f, "<tr><td><a href=\"#s%d\">%s</a></td><td>%s</td>", i + 1, html(s->name),
                s->program ? "program" : "images");
        for (int t = 0; t < TALLY_COUNT; t++)
            fprintf(f, "<td class=\"n%s\">%d</td>", s->tally[t] == 0 ? " zero" : "", s->tally[t]);
        /* A square a scene, in its verdict's colour, named when pointed at. */
        fputs("<td class=\"dots\">", f);
        for (int k = 0; k < g->render_count; k++) {
            const VerdictInfo *v = &verdict_info[s->results[k].verdict];
            fprintf(f, "<span class=\"dot %s\" title=\"%s: %s\"></span>", tally_class[v->tally],
                    html(g->renders[k].name), v->name);
        }
        fprintf(f, "</td><td>%s%s</td></tr>\n", badge(g, s, -1), copy_flag(copies(g, s)));
    }
    fputs("</tbody>\n</table>\n</section>\n", f);
}

/* Writes a figure of scene k: the reference's picture with classes `same` when it stands
 * for this one, else the thumbnail at path (width its share of the column: an image of
 * another size is shown at its relative size), else a box of the reference's shape
 * saying `none`. */
static void write_figure(FILE *f, const char *same, const char *path, double width, int k,
                         const char *alt, const char *caption, const char *none)
{
    int w, h;
    fputs("<figure>", f);
    if (same != NULL)
        fprintf(f, "<div class=\"pic %s%d\" role=\"img\" aria-label=\"%s\"></div>", same, k, alt);
    else if (picture_size(path, &w, &h)) {
        fprintf(f, "<img class=\"pic%s\" width=\"%d\" height=\"%d\" style=\"width:%.1f%%\" "
                   "alt=\"%s\" src=\"", w <= PIXELATED_WIDTH ? " px" : "", w, h, 100 * width, alt);
        put_picture(f, path);
        fputs("\">", f);
    } else /* the reference's rule gives the box its shape; .pic.none wins its background */
        fprintf(f, "<div class=\"pic none ref%d\">%s</div>", k, none);
    fprintf(f, "<figcaption>%s</figcaption></figure>\n", caption);
}

/* Writes the pictures of a scene side by side, the reference, the submitted image and the
 * heat map (the reference's picture and a black one for an identical image), with imgdiff's
 * figures. */
static void write_pictures(FILE *f, const SceneResult *res, int k, bool statistics)
{
    const Figures *fig = &res->figures;
    double width = res->relative_width > 0 && res->relative_width < 1 ? res->relative_width : 1;
    char *caption = "Differences";
    if (statistics && res->compared)
        caption = grade_format("Bias test: each 8 x 8 block's largest |z|, black within "
                               "rounding, white at the critical |z| = %.3g (fails); pixels "
                               "compared exactly that differ, white",
                               fig->heat_scale);
    else if (res->identical)
        caption = "Differences: none, the images are identical";
    else if (res->compared)
        caption = grade_format("Differences: black where equal, white at %.3g/255",
                               fig->heat_scale * 255);
    fputs("<div class=\"pictures\">\n", f);
    write_figure(f, "ref", NULL, 1, k, "reference image", "Reference", NULL);
    write_figure(f, res->identical ? "ref" : NULL, res->image_show, width, k, "submitted image",
                 "Submission", "no image");
    write_figure(f, res->identical ? "black ref" : NULL, res->heat_show, 1, k,
                 "heat map of the differences", caption, "no comparison");
    if (statistics && res->compared)
        fprintf(f,
                "<table class=\"figures\"><tr><th>Bias: largest |z|</th><td>%.3g (fails beyond "
                "%.3g)</td></tr><tr><th>Noise, times raytra's</th><td>%.3g (from %.3g to %.3g)"
                "</td></tr><tr><th>Exact pixels differing</th><td>%ld</td></tr><tr><th>Pixels "
                "faulted</th><td>%ld (%.3g%%)</td></tr><tr><th>RMSE from the mean</th><td>%.4g"
                "</td></tr></table>\n",
                fabs(fig->bias_z), fig->bias_critical, fig->noise, fig->noise_low,
                fig->noise_high, fig->exact, fig->differing, 100.0 * fig->differing / fig->pixels,
                fig->rmse);
    else if (res->compared)
        fprintf(f,
                "<table class=\"figures\"><tr><th>Max diff R, G, B</th><td>%.3g, %.3g, %.3g /255"
                "</td></tr><tr><th>Mean abs diff</th><td>%.3g /255</td></tr><tr><th>RMSE</th><td>"
                "%.4g</td></tr><tr><th>PSNR</th><td>%s</td></tr><tr><th>Differing pixels</th><td>"
                "%ld (%.3g%%)</td></tr>%s</table>\n",
                fig->max[0] * 255, fig->max[1] * 255, fig->max[2] * 255, fig->mean * 255,
                fig->rmse,
                isinf(fig->psnr) ? "&infin; (equal)" : grade_format("%.2f dB", fig->psnr),
                fig->differing, 100.0 * fig->differing / fig->pixels,
                fig->differing > 0
                    ? grade_format("<tr><th>Region</th><td>(%d,%d)&ndash;(%d,%d)</td></tr>",
                                   fig->box[0], fig->box[1], fig->box[2], fig->box[3])
                    : "");
    fputs("</div>\n", f);
}

/* Returns the command line a scene was run with, from the report's folder: "cd
 * work/03-alice/run && ../build/raytra SCENE ../images/IMAGE". */
char *report_command(const Submission *s, const SceneResult *res)
{
    char *run = grade_format("work/%s/run", strrchr(s->work, '/') + 1);
    return grade_format("cd %s && %s", run_quote(run), res->command);
}

/* Writes a block of a program's output, or nothing when there is none. */
static void write_log(FILE *f, const char *title, const char *log, bool open)
{
    if (log != NULL)
        fprintf(f, "<details class=\"log\"%s><summary>%s</summary><pre>%s</pre></details>\n",
                open ? " open" : "", title, html(log));
}

/* Writes the whole page: the heading and summary, then a section a submission with its
 * verdict, its build, and a line a scene that opens (open already unless it passed) on the
 * scene file, the pictures when there is an image, and the program's output. */
static void write_html(FILE *f, const Grading *g)
{
    write_heading(f, g);
    for (int i = 0; i < g->sub_count; i++) {
        const Submission *s = &g->subs[i];
        bool broken = s->build_message != NULL;
        fprintf(f, "<section id=\"s%d\">\n<h2><span class=\"name\">%s</span><span class=\"kind\">"
                   "%s</span>%s<a class=\"back\" href=\"#summary\">&uarr; summary</a></h2>\n",
                i + 1, html(s->name), s->program ? "program" : "images", badge(g, s, -1));
        if (broken)
            fprintf(f, "<div class=\"broken\"><strong>The build failed:</strong> %s. No scene "
                       "could be rendered.", html(s->build_message));
        else {
            double max, got = part_points(g, s, &max);
            fprintf(f, "<p class=\"counts\">%d of %d scene%s pass: %g of %g points.</p>\n",
                    s->tally[TALLY_PASS], g->render_count, plural(g->render_count), got, max);
        }
        if (s->removed != NULL)
            fprintf(f, "<p class=\"file\">Build outputs it carried, removed before make: "
                       "<code>%s</code></p>\n", html(s->removed));
        write_log(f, "Build output (the last lines)", s->build_log_tail, broken);
        for (int k = 0; k < g->render_count && !broken; k++) {
            const Render *r = &g->renders[k];
            const SceneResult *res = &s->results[k];
            fprintf(f,
                    "<details class=\"scene\"%s>\n<summary><span class=\"scene-name\">%s</span>"
                    "%s%s<span class=\"message\">%s</span>%s</summary>\n<div class=\"scene-body\">"
                    "\n<p class=\"file\">Scene <code>%s",
                    res->verdict == VERDICT_PASS ? "" : " open",
                    r->hidden ? grade_format("%s (hidden)", html(r->name)) : html(r->name),
                    badge(g, s, k),
                    copy_flag(res->copy), html(res->message),
                    res->seconds > 0
                        ? grade_format("<span class=\"time\">%.2f s</span>", res->seconds)
                        : "",
                    html(r->scene));
            for (char **a = r->argv + RENDER_WORDS; *a != NULL; a++)
                fprintf(f, " %s", html(*a));
            fputs("</code></p>\n", f);
            /* What was run, where (from the report's folder), to run it again by hand. */
            if (res->command != NULL)
                fprintf(f, "<p class=\"file\">Command <code>%s</code></p>\n",
                        html(report_command(s, res)));
            if (res->compared || res->relative_width > 0)
                write_pictures(f, res, k, r->statistical);
            write_log(f, "Program output (the last lines)",
                      res->command != NULL && res->log_tail == NULL ? "(nothing)" : res->log_tail,
                      verdict_info[res->verdict].tally == TALLY_ERROR);
            fputs("</div>\n</details>\n", f);
        }
        fputs(broken ? "</div>\n</section>\n" : "</section>\n", f);
    }
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

/* Writes grades.csv and report.html into g->out; false (reported) when it cannot. */
bool report_write(const Grading *g)
{
    char *table = grade_format("%s/grades.csv", g->out);
    char *page = grade_format("%s/report.html", g->out);
    if (!report_write_whole(table, g, csv_write) || !report_write_whole(page, g, write_html))
        return false;
    fprintf(g->progress, "grade: wrote %s and %s\n", page, table);
    return true;
}
