/* grade_report.c: report.html, one self-contained page, and grades.csv, each written whole. */
#include "grade.h"

#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "imgfile.h"
#include "outfile.h"

/* A thumbnail this narrow or narrower is shown enlarged with sharp pixels. */
#define PIXELATED_WIDTH 200

/* The largest picture embedded: thumbnails are far smaller; a larger file is a mistake. */
#define EMBED_MAX_BYTES (8L << 20)

/* Each verdict's name, column and meaning; in the order of Verdict. */
const VerdictInfo verdict_info[VERDICT_COUNT] = {
    {"PASS", TALLY_PASS, "the image matches the reference within the tolerances"},
    {"FAIL", TALLY_FAIL, "the image differs from the reference by more than the tolerances allow"},
    {"WRONG SIZE", TALLY_FAIL, "the image has another width or height than the reference"},
    {"LINK", TALLY_FAIL,
     "the file is a symbolic link, or a hard link to the reference: not an image handed in"},
    {"UNREADABLE", TALLY_FAIL,
     "the file is not a PNG, PFM or OpenEXR image that imgdiff can read, or not a regular file"},
    {"MISSING", TALLY_MISSING,
     "there is no image: none in the folder, or the program ended normally without writing it"},
    {"ERROR", TALLY_ERROR, "the program ended with a failure exit status and wrote no image"},
    {"CRASHED", TALLY_ERROR,
     "the program was killed by a signal: a segmentation fault, an abort, a file too large"},
    {"TIMEOUT", TALLY_ERROR,
     "the program did not finish within the time limit; it was killed, with all it started"},
    {"OUT OF MEMORY", TALLY_ERROR,
     "the program failed saying that it ran out of memory, or was killed as the system's "
     "out-of-memory killer kills"},
    {"BUILD FAILED", TALLY_ERROR,
     "make failed, ran too long or made no raytra: no scene could be rendered"},
};

/* The summary's class (and colour) for each tally. */
static const char *const tally_class[TALLY_COUNT] = {"pass", "fail", "missing", "error"};

/* The page's style sheet: grade_report.css, made a C string by the build (grade.mk), which
 * must stay under the 4095 bytes ISO C promises a string. */
static const char style[] =
#include "grade_style.h"
    ;

/* The page's parts, filled by html_put. */
static const char page_head[] =
    "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
    "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
    "<title>%s: grading report</title>\n<style>\n%S";
static const char page_title[] =
    "</style>\n</head>\n<body>\n<header class=\"page\"><div>\n<h1>Grading report: part %s</h1>\n"
    "<p class=\"meta\">%d submission%S from <code>%s</code>, %d scene%S each, graded %s.</p>\n"
    "<p class=\"meta\">A pixel differs when one of its channels differs by more than %s; an "
    "image passes when at most the fraction %s of its pixels differ. A program gets %s s a "
    "scene and %s s to build; memory limit: %s.</p>\n";
static const char summary_head[] =
    "</div></header>\n<main>\n<section id=\"summary\">\n<h2>Summary</h2>\n<p class=\"counts\">"
    "%d of %d submission%S pass every scene.</p>\n<table class=\"summary\">\n<thead><tr>"
    "<th>Submission</th><th>Kind</th><th class=\"n\">Pass</th><th class=\"n\">Fail</th>"
    "<th class=\"n\">Missing</th><th class=\"n\">Error</th><th>Scenes</th><th>Verdict</th>"
    "</tr></thead>\n<tbody>\n";
static const char legend_head[] =
    "</tbody>\n</table>\n<details><summary>What the verdicts mean, and how they are counted"
    "</summary>\n<dl class=\"legend\">\n";
static const char scene_head[] =
    "<details class=\"scene\"%S>\n<summary><span class=\"scene-name\">%s</span><span "
    "class=\"badge %S\">%S</span><span class=\"message\">%s</span>%S</summary>\n<div "
    "class=\"scene-body\">\n<p class=\"file\">Scene <code>%s";
static const char submission_head[] =
    "<section id=\"s%d\">\n<h2><span class=\"name\">%s</span><span class=\"kind\">%S</span><span "
    "class=\"badge %S\">%S</span><a class=\"back\" href=\"#summary\">&uarr; summary</a></h2>\n";
static const char page_end[] =
    "</main>\n<footer>Written by raytra's <code>tools/grade</code> (docs/grading.md). The "
    "builds, images, logs and heat maps are in <code>%s</code>.</footer>\n</body>\n</html>\n";

/* Writes the template fmt with its conversions filled: %s a text with the characters HTML
 * gives a meaning made plain, %S raw HTML, %d an int. */
static void html_put(FILE *f, const char *fmt, ...)
{
    static const char specials[] = "&<>\"'", *const entities[] = {"&amp;", "&lt;", "&gt;",
                                                                  "&quot;", "&#39;"};
    va_list ap;
    va_start(ap, fmt);
    for (const char *p = fmt; *p != '\0'; p++) {
        if (*p != '%' || p[1] == '\0' || strchr("sSd", p[1]) == NULL) {
            fputc(*p, f);
        } else if (*++p == 'd') {
            fprintf(f, "%d", va_arg(ap, int));
        } else if (*p == 'S') {
            fputs(va_arg(ap, const char *), f);
        } else {
            for (const char *t = va_arg(ap, const char *); t != NULL && *t != '\0'; t++) {
                const char *special = strchr(specials, *t);
                if (special != NULL)
                    fputs(entities[special - specials], f);
                else
                    fputc(*t, f);
            }
        }
    }
    va_end(ap);
}

/* Returns "s" for a count other than 1, the plural's ending. */
static const char *plural(int n)
{
    return n == 1 ? "" : "s";
}

/* Returns the thumbnail at path, a PNG the grader made, as a data: URI (base64) for the
 * caller to free, with its size in pixels; NULL when it cannot be read. */
static char *picture_uri(const char *path, int *width, int *height)
{
    static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    ImgFileKind kind;
    Error err;
    struct stat st;
    if (path == NULL || !imgfile_header(path, &kind, width, height, &err) || kind != IMGFILE_PNG)
        return NULL;
    FILE *in = imgfile_fopen(path);
    bool ok = in != NULL && fstat(fileno(in), &st) == 0 && st.st_size <= EMBED_MAX_BYTES;
    size_t size = ok ? (size_t)st.st_size : 0;
    unsigned char *d = calloc(1, size + 2); /* two bytes more, zeroed, for base64's last group */
    char *uri = malloc(size / 3 * 4 + 32), *u = uri;
    ok = ok && d != NULL && uri != NULL && fread(d, 1, size, in) == size;
    u += ok ? sprintf(uri, "data:image/png;base64,") : 0;
    for (size_t i = 0; ok && i < size; i += 3, u += 4) {
        unsigned long bits = (unsigned long)d[i] << 16 | (unsigned long)d[i + 1] << 8 | d[i + 2];
        u[0] = digits[(bits >> 18) & 63];
        u[1] = digits[(bits >> 12) & 63];
        u[2] = i + 1 < size ? digits[(bits >> 6) & 63] : '=';
        u[3] = i + 2 < size ? digits[bits & 63] : '=';
        u[4] = '\0';
    }
    if (in != NULL)
        fclose(in);
    free(d);
    if (!ok)
        free(uri);
    return ok ? uri : NULL;
}

/* Returns a submission's overall verdict: PASS when every scene passes, BUILD FAILED, or
 * FAIL. */
static const VerdictInfo *overall(const Grading *g, const Submission *s)
{
    return &verdict_info[s->build_message[0] != '\0'               ? VERDICT_BUILD_FAILED
                         : s->tally[TALLY_PASS] == g->render_count ? VERDICT_PASS
                                                                   : VERDICT_FAIL];
}

/* Writes the page's head, with a style rule a reference picture, each embedded once and
 * shown as a background beside every submission's image; and the title block. */
static void write_heading(FILE *f, const Grading *g)
{
    html_put(f, page_head, g->part, style);
    for (int k = 0; k < g->render_count; k++) {
        int w, h;
        char *uri = picture_uri(g->renders[k].reference_show, &w, &h);
        if (uri != NULL)
            fprintf(f, ".ref%d{aspect-ratio:%d/%d;background-image:url(%s)}\n", k, w, h, uri);
        free(uri);
    }
    html_put(f, page_title, g->part, g->sub_count, plural(g->sub_count), g->submissions,
             g->render_count, plural(g->render_count), g->started, g->threshold, g->allow,
             grade_format("%g", g->time_limit), grade_format("%g", g->build_time_limit),
             grade_size_text(g->memory_limit));
    if (g->illustrations != NULL)
        html_put(f, "<p class=\"meta\">Not graded (illustrations): %s.</p>\n", g->illustrations);
}

/* Writes the summary: a row a submission, linking to its details, and the legend. */
static void write_summary(FILE *f, const Grading *g)
{
    int passed = 0;
    for (int i = 0; i < g->sub_count; i++)
        passed += g->subs[i].tally[TALLY_PASS] == g->render_count;
    html_put(f, summary_head, passed, g->sub_count, plural(g->sub_count));
    for (int i = 0; i < g->sub_count; i++) {
        const Submission *s = &g->subs[i];
        html_put(f, "<tr><td><a href=\"#s%d\">%s</a></td><td>%S</td>", i + 1, s->name,
                 s->program ? "program" : "images");
        for (int t = 0; t < TALLY_COUNT; t++)
            html_put(f, "<td class=\"n%S\">%d</td>", s->tally[t] == 0 ? " zero" : "", s->tally[t]);
        /* A square a scene, in its verdict's colour, named when pointed at. */
        fputs("<td class=\"dots\">", f);
        for (int k = 0; k < g->render_count; k++) {
            const VerdictInfo *v = &verdict_info[s->results[k].verdict];
            html_put(f, "<span class=\"dot %S\" title=\"%s: %S\"></span>", tally_class[v->tally],
                     g->renders[k].name, v->name);
        }
        html_put(f, "</td><td><span class=\"badge %S\">%S</span></td></tr>\n",
                 tally_class[overall(g, s)->tally], overall(g, s)->name);
    }
    html_put(f, legend_head);
    for (const VerdictInfo *v = verdict_info; v < verdict_info + VERDICT_COUNT; v++)
        html_put(f, "<dt><span class=\"badge %S\">%S</span></dt><dd>%S; counted as %S</dd>\n",
                 tally_class[v->tally], v->name, v->meaning, tally_class[v->tally]);
    fputs("</dl>\n</details>\n</section>\n", f);
}

/* Writes a block of a program's output, or nothing when there is none. */
static void write_log(FILE *f, const char *title, const char *log, bool open)
{
    if (log != NULL)
        html_put(f, "<details class=\"log\"%S><summary>%S</summary><pre>%s</pre></details>\n",
                 open ? " open" : "", title, log);
}

/* Writes a figure of scene k: the reference's picture with classes `same` when it stands
 * for this one, else the thumbnail at path (width its share of the column: an image of
 * another size is shown at its relative size), else a box of the reference's shape
 * saying `none`. */
static void write_figure(FILE *f, const char *same, const char *path, double width, int k,
                         const char *alt, const char *caption, const char *none)
{
    int w, h;
    char *uri = same == NULL ? picture_uri(path, &w, &h) : NULL;
    fputs("<figure>", f);
    if (same != NULL)
        html_put(f, "<div class=\"pic %S%d\" role=\"img\" aria-label=\"%S\"></div>", same, k, alt);
    else if (uri != NULL)
        fprintf(f,
                "<img class=\"pic%s\" width=\"%d\" height=\"%d\" style=\"width:%.1f%%\" "
                "alt=\"%s\" src=\"%s\">",
                w <= PIXELATED_WIDTH ? " px" : "", w, h, 100 * width, alt, uri);
    else /* the reference's rule gives the box its shape; .pic.none wins its background */
        fprintf(f, "<div class=\"pic none ref%d\">%s</div>", k, none);
    html_put(f, "<figcaption>%S</figcaption></figure>\n", caption);
    free(uri);
}

/* Writes the pictures of a scene side by side, the reference, the submitted image and the
 * heat map (the reference's picture and a black one for an identical image), with imgdiff's
 * figures. */
static void write_pictures(FILE *f, const SceneResult *res, int k)
{
    const Figures *fig = &res->figures;
    char caption[128] = "Differences", psnr[32] = "&infin; (equal)", box[128] = "";
    if (res->identical)
        snprintf(caption, sizeof caption, "Differences: none, the images are identical");
    else if (res->heat_show != NULL)
        snprintf(caption, sizeof caption, "Differences: black where equal, white at %.3g/255",
                 fig->heat_scale * 255);
    double width = res->relative_width > 0 && res->relative_width < 1 ? res->relative_width : 1;
    fputs("<div class=\"pictures\">\n", f);
    write_figure(f, "ref", NULL, 1, k, "reference image", "Reference", NULL);
    write_figure(f, res->identical ? "ref" : NULL, res->image_show, width, k, "submitted image",
                 "Submission", "no image");
    write_figure(f, res->identical ? "black ref" : NULL, res->heat_show, 1, k,
                 "heat map of the differences", caption, "no comparison");
    if (!isinf(fig->psnr))
        snprintf(psnr, sizeof psnr, "%.2f dB", fig->psnr);
    if (fig->has_box)
        snprintf(box, sizeof box, "<tr><th>Region</th><td>(%d,%d)&ndash;(%d,%d)</td></tr>",
                 fig->box[0], fig->box[1], fig->box[2], fig->box[3]);
    if (res->compared)
        fprintf(f,
                "<table class=\"figures\"><tr><th>Max diff R, G, B</th><td>%.3g, %.3g, %.3g /255"
                "</td></tr><tr><th>Mean abs diff</th><td>%.3g /255</td></tr><tr><th>RMSE</th><td>"
                "%.4g</td></tr><tr><th>PSNR</th><td>%s</td></tr><tr><th>Differing pixels</th><td>"
                "%ld (%.3g%%)</td></tr>%s</table>\n",
                fig->max[0] * 255, fig->max[1] * 255, fig->max[2] * 255, fig->mean * 255,
                fig->rmse, psnr, fig->differing,
                fig->pixels > 0 ? 100.0 * fig->differing / fig->pixels : 0.0, box);
    fputs("</div>\n", f);
}

/* Writes one scene of one submission: a line that opens (open already unless it passed)
 * on the scene file, the pictures when there is an image, and the program's output. */
static void write_scene(FILE *f, const Grading *g, const Submission *s, int k)
{
    const Render *r = &g->renders[k];
    const SceneResult *res = &s->results[k];
    Tally tally = verdict_info[res->verdict].tally;
    char seconds[64] = "";
    if (res->seconds >= 0)
        snprintf(seconds, sizeof seconds, "<span class=\"time\">%.2f s</span>", res->seconds);
    html_put(f, scene_head, res->verdict == VERDICT_PASS ? "" : " open", r->name,
             tally_class[tally], verdict_info[res->verdict].name, res->message, seconds, r->scene);
    for (char **a = r->args; *a != NULL; a++)
        html_put(f, " %s", *a);
    fputs("</code></p>\n", f);
    if (res->identical || res->image_show != NULL)
        write_pictures(f, res, k);
    write_log(f, "Program output (the last lines)", res->log_tail, tally == TALLY_ERROR);
    fputs("</div>\n</details>\n", f);
}

/* Writes the whole page: the heading, the summary, then a section a submission with its
 * verdict, its build, and each of its scenes. */
static void write_html(FILE *f, const Grading *g)
{
    write_heading(f, g);
    write_summary(f, g);
    for (int i = 0; i < g->sub_count; i++) {
        const Submission *s = &g->subs[i];
        bool broken = s->build_message[0] != '\0';
        html_put(f, submission_head, i + 1, s->name, s->program ? "program" : "images",
                 tally_class[overall(g, s)->tally], overall(g, s)->name);
        if (broken)
            html_put(f, "<div class=\"broken\"><strong>The build failed:</strong> %s. No scene "
                        "could be rendered.", s->build_message);
        else
            html_put(f, "<p class=\"counts\">%d of %d scene%S pass.</p>\n", s->tally[TALLY_PASS],
                     g->render_count, plural(g->render_count));
        write_log(f, "Build output (the last lines)", s->build_log_tail, broken);
        for (int k = 0; k < g->render_count && !broken; k++)
            write_scene(f, g, s, k);
        fputs(broken ? "</div>\n</section>\n" : "</section>\n", f);
    }
    html_put(f, page_end, g->work);
}

/* Writes g->out/name with write, through a temporary renamed onto it so that it appears
 * only complete; returns its path, or NULL (reported) on any failure. */
static char *write_whole(const Grading *g, const char *name, void (*write)(FILE *, const Grading *))
{
    char *path = grade_format("%s/%s", g->out, name);
    OutFile out;
    Error err;
    bool ok = outfile_open(&out, path, &err);
    if (ok) {
        write(out.file, g);
        if (ferror(out.file)) {
            error_set(&err, "write error");
            outfile_abort(&out);
            ok = false;
        } else {
            ok = outfile_commit(&out, &err);
        }
    }
    if (!ok)
        fprintf(stderr, "grade: cannot write %s: %s\n", path, err.text);
    return ok ? path : NULL;
}

/* Writes grades.csv and report.html into g->out; false (reported) when it cannot. */
bool report_write(const Grading *g)
{
    char *csv = write_whole(g, "grades.csv", csv_write);
    char *html = csv != NULL ? write_whole(g, "report.html", write_html) : NULL;
    if (html != NULL && !g->quiet)
        fprintf(stderr, "grade: wrote %s and %s\n", html, csv);
    return html != NULL;
}

/* Prints, for a student checking their own work, each scene's verdict and reason, and the
 * heat map to look at when it did not pass; returns the exit status: 0 when every scene
 * passes, 1 otherwise. */
int report_print_self(const Grading *g)
{
    const Submission *s = &g->subs[0];
    for (int k = 0; k < g->render_count; k++) {
        const SceneResult *res = &s->results[k];
        char *heat = grade_format("%s/%s.heat.png", s->work, g->renders[k].name);
        printf("%-12s %s: %s\n", verdict_info[res->verdict].name, g->renders[k].name, res->message);
        if (res->verdict != VERDICT_PASS && access(heat, F_OK) == 0)
            printf("%12s heat map: %s\n", "", heat);
    }
    printf("%d of %d scenes pass; the report: %s/report.html\n", s->tally[TALLY_PASS],
           g->render_count, g->out);
    return s->tally[TALLY_PASS] == g->render_count ? 0 : 1;
}
