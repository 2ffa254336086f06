/* grade_report.c: writing grades.csv and report.html (images inside), each appearing only whole. */
#include "grade_report.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "imgfile.h"
#include "outfile.h"

/* The largest picture embedded: thumbnails are far smaller; a larger file is a mistake. */
#define EMBED_MAX_BYTES (8L << 20)

/* A thumbnail this narrow or narrower is shown enlarged with sharp pixels. */
#define PIXELATED_WIDTH 200

/* What each verdict means, for the report's legend; in the order of Verdict. */
static const char *const meanings[VERDICT_COUNT] = {
    "the image matches the reference within the tolerances",
    "the image differs from the reference by more than the tolerances allow",
    "the image has another width or height than the reference",
    "the file is a symbolic link, or a hard link to the reference: not an image handed in",
    "the file is not a PNG, PFM or EXR image that imgdiff can read, or not a regular file",
    "there is no image: none in the folder, or the program ended normally without writing it",
    "the program ended with a failure exit status and wrote no image",
    "the program was killed by a signal: a segmentation fault, an abort, a file too large",
    "the program did not finish within the time limit; it was killed, with all it started",
    "the program failed saying that it ran out of memory, or was killed as the system's "
    "out-of-memory killer kills",
    "make failed, ran too long or made no raytra: no scene could be rendered",
};

/* The summary's class (and colour) for each tally. */
static const char *const tally_class[TALLY_COUNT] = {"pass", "fail", "missing", "error"};

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
static void write_csv(FILE *f, const Grading *g)
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
            csv_field(f, verdict_name(res->verdict), true, ',');
            for (int c = 3; c <= 11; c++)
                csv_field(f, v[c], false, ',');
            csv_field(f, res->message, true, ',');
            csv_field(f, v[13], false, '\n');
        }
}

/* Writes the file at path through a temporary renamed onto it, so that it appears only
 * complete; false (err) on any failure. */
static bool write_whole(const char *path, void (*write)(FILE *, const Grading *), const Grading *g,
                        Error *err)
{
    OutFile out;
    if (!outfile_open(&out, path, err))
        return false;
    write(out.file, g);
    if (ferror(out.file)) {
        error_set(err, "write error");
        outfile_abort(&out);
        return false;
    }
    return outfile_commit(&out, err);
}

/* Writes grades.csv to path; false (err) when it cannot. */
bool report_write_csv(const Grading *g, const char *path, Error *err)
{
    return write_whole(path, write_csv, g, err);
}

/* Writes text with the characters HTML gives a meaning made plain. */
static void html_text(FILE *f, const char *text)
{
    for (const char *p = text; p != NULL && *p != '\0'; p++)
        switch (*p) {
        case '&': fputs("&amp;", f); break;
        case '<': fputs("&lt;", f); break;
        case '>': fputs("&gt;", f); break;
        case '"': fputs("&quot;", f); break;
        case '\'': fputs("&#39;", f); break;
        default: fputc(*p, f);
        }
}

/* Reads the whole file at path, if it is at most EMBED_MAX_BYTES; NULL otherwise. */
static unsigned char *read_small_file(const char *path, size_t *size)
{
    struct stat st;
    FILE *f = imgfile_fopen(path);
    unsigned char *data = NULL;
    if (f != NULL && fstat(fileno(f), &st) == 0 && st.st_size <= EMBED_MAX_BYTES) {
        data = grade_alloc((size_t)st.st_size + 1);
        *size = fread(data, 1, (size_t)st.st_size, f);
        if (ferror(f) || *size != (size_t)st.st_size) {
            free(data);
            data = NULL;
        }
    }
    if (f != NULL)
        fclose(f);
    return data;
}

/* Writes the bytes data[0..size) in base64. */
static void write_base64(FILE *f, const unsigned char *data, size_t size)
{
    static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    for (size_t i = 0; i < size; i += 3) {
        unsigned long bits = (unsigned long)data[i] << 16;
        if (i + 1 < size)
            bits |= (unsigned long)data[i + 1] << 8;
        if (i + 2 < size)
            bits |= data[i + 2];
        fputc(digits[(bits >> 18) & 63], f);
        fputc(digits[(bits >> 12) & 63], f);
        fputc(i + 1 < size ? digits[(bits >> 6) & 63] : '=', f);
        fputc(i + 2 < size ? digits[bits & 63] : '=', f);
    }
}

/* A PNG thumbnail read for embedding: its bytes and its size in pixels. */
typedef struct {
    unsigned char *data;
    size_t size;
    int width, height;
} Picture;

/* Reads the PNG at path (a thumbnail the grader made) into p; false when it cannot. */
static bool picture_read(const char *path, Picture *p)
{
    *p = (Picture){0};
    if (path == NULL || (p->data = read_small_file(path, &p->size)) == NULL)
        return false;
    /* The width and height are the first fields of the IHDR chunk, after 16 bytes. */
    const unsigned char *d = p->data;
    if (p->size < 24 || memcmp(d, "\x89PNG", 4) != 0) {
        free(p->data);
        p->data = NULL;
        return false;
    }
    p->width = (int)((unsigned)d[16] << 24 | (unsigned)d[17] << 16 | (unsigned)d[18] << 8 | d[19]);
    p->height = (int)((unsigned)d[20] << 24 | (unsigned)d[21] << 16 | (unsigned)d[22] << 8 | d[23]);
    return p->width > 0 && p->height > 0;
}

/* The style sheet, a rule or a few a line. */
static const char *const style_rules[] = {
    ":root{--pass:#1a7f37;--pass-bg:#dafbe1;--fail:#cf222e;--fail-bg:#ffebe9;"
    "--missing:#57606a;--missing-bg:#eaeef2;--error:#8250df;--error-bg:#f6edfe;"
    "--line:#d0d7de;--soft:#eaeef2;--muted:#59636e;--text:#1f2328}",
    "*{box-sizing:border-box}",
    "body{margin:0;"
    "font:14px/1.45 system-ui,-apple-system,'Segoe UI',Roboto,'Helvetica Neue',Arial,sans-serif;"
    "color:var(--text);background:#f6f8fa}",
    "header.page{background:#fff;border-bottom:1px solid var(--line)}",
    "header.page>div,main,footer{max-width:1240px;margin:0 auto;padding-left:28px;"
    "padding-right:28px}",
    "header.page>div{padding-top:20px;padding-bottom:14px}",
    "h1{margin:0 0 6px;font-size:22px;font-weight:600}",
    ".meta{color:var(--muted);margin:2px 0}",
    "main{padding-top:22px;padding-bottom:8px}",
    "code{font:12.5px ui-monospace,SFMono-Regular,Menlo,Consolas,monospace;"
    "background:#eff1f3;padding:1px 5px;border-radius:4px}",
    "section{background:#fff;border:1px solid var(--line);border-radius:8px;"
    "padding:16px 20px;margin-bottom:20px}",
    "h2{font-size:18px;margin:0 0 10px;display:flex;align-items:center;gap:10px;flex-wrap:wrap}",
    "h2 .name{overflow-wrap:anywhere}",
    "a{color:#0969da;text-decoration:none}a:hover{text-decoration:underline}",
    ".back{margin-left:auto;font-size:12.5px;font-weight:400}",
    "table.summary{border-collapse:collapse;width:100%}",
    "table.summary th,table.summary td{padding:7px 10px;"
    "border-bottom:1px solid var(--soft);text-align:left}",
    "table.summary tr:last-child td{border-bottom:0}",
    "table.summary th{font-size:11.5px;text-transform:uppercase;letter-spacing:.04em;"
    "color:var(--muted);font-weight:600}",
    "table.summary td:first-child{overflow-wrap:anywhere;min-width:8em}",
    ".n{text-align:right!important;font-variant-numeric:tabular-nums;width:64px}",
    "td.zero{color:#b8bfc6}",
    ".dots{white-space:nowrap}",
    ".dot{display:inline-block;width:11px;height:11px;border-radius:3px;margin-right:3px;"
    "vertical-align:middle}",
    ".dot.pass{background:#2da44e}.dot.fail{background:var(--fail)}.dot.missing{"
    "background:#afb8c1}.dot.error{background:var(--error)}",
    ".badge{display:inline-block;font-size:11px;font-weight:700;letter-spacing:.04em;"
    "padding:2px 9px;border-radius:999px;white-space:nowrap;vertical-align:middle}",
    ".badge.pass{color:var(--pass);background:var(--pass-bg)}",
    ".badge.fail{color:var(--fail);background:var(--fail-bg)}",
    ".badge.missing{color:var(--missing);background:var(--missing-bg)}",
    ".badge.error{color:var(--error);background:var(--error-bg)}",
    ".kind{font-size:12px;color:var(--muted);border:1px solid var(--line);"
    "border-radius:999px;padding:0 8px;font-weight:500}",
    ".counts{color:var(--muted);margin:0 0 4px}",
    "details.scene{border-top:1px solid var(--soft)}",
    "details.scene>summary{display:flex;align-items:center;gap:10px;padding:9px 2px;"
    "list-style:none;cursor:pointer}",
    "details.scene>summary::-webkit-details-marker{display:none}",
    "details.scene>summary::before{content:'';border-left:6px solid var(--muted);"
    "border-top:4px solid transparent;border-bottom:4px solid transparent}",
    "details.scene[open]>summary::before{transform:rotate(90deg)}",
    "details.scene>summary:hover{background:#f6f8fa}",
    ".scene-name{font-weight:600;min-width:200px}",
    ".message{flex:1}",
    ".message::first-letter{text-transform:uppercase}",
    ".time{color:var(--muted);font-size:12.5px;font-variant-numeric:tabular-nums}",
    ".scene-body{padding:0 0 14px 16px}",
    ".file{color:var(--muted);font-size:12.5px;margin:0 0 8px}",
    ".pictures{display:grid;grid-template-columns:repeat(3,minmax(0,1fr)) 240px;gap:16px;"
    "align-items:start}",
    "figure{margin:0}",
    ".pic{display:block;width:100%;height:auto;border:1px solid var(--line);"
    "border-radius:4px;background:#000 no-repeat;background-size:100% 100%}",
    ".px{image-rendering:pixelated}",
    ".pic.none{display:flex;align-items:center;justify-content:center;text-align:center;"
    "padding:8px;color:var(--muted);font-size:13px;"
    "background:repeating-linear-gradient(45deg,#f6f8fa 0 8px,#eef1f4 8px 16px)}",
    ".pic.black{background:#000}",
    "figcaption{font-size:12px;color:var(--muted);margin-top:4px}",
    "table.figures{border-collapse:collapse;font-size:12.5px;width:100%}",
    "table.figures th{text-align:left;font-weight:500;color:var(--muted);"
    "padding:2px 10px 2px 0;white-space:nowrap;vertical-align:top}",
    "table.figures td{padding:2px 0;font-variant-numeric:tabular-nums}",
    "details.log pre{background:#f6f8fa;border:1px solid var(--line);border-radius:6px;"
    "padding:8px 10px;font-size:12px;max-height:260px;overflow:auto;white-space:pre-wrap;"
    "overflow-wrap:anywhere;margin:6px 0 0}",
    "details.log>summary{cursor:pointer;color:var(--muted);font-size:12.5px;margin-top:8px}",
    ".broken{border-left:3px solid var(--error);background:var(--error-bg);"
    "padding:8px 12px;border-radius:4px;margin-top:6px}",
    "dl.legend{display:grid;grid-template-columns:max-content 1fr;gap:4px 12px;"
    "margin:10px 0 0;font-size:13px}",
    "dl.legend dd{margin:0;color:var(--muted)}",
    "footer{color:var(--muted);font-size:12px;padding-bottom:28px}",
    "@media (max-width:900px){.pictures{grid-template-columns:repeat(2,minmax(0,1fr))}}",
};

/* Writes the style sheet, with one rule a reference picture: each is embedded once and
 * shown, as a background, beside every submission's image. */
static void write_style(FILE *f, const Grading *g)
{
    for (size_t k = 0; k < sizeof style_rules / sizeof style_rules[0]; k++)
        fprintf(f, "%s\n", style_rules[k]);
    for (int k = 0; k < g->render_count; k++) {
        Picture p;
        if (!picture_read(g->renders[k].reference_show, &p))
            continue;
        fprintf(f, ".ref%d{aspect-ratio:%d/%d;background-image:url(data:image/png;base64,", k,
                p.width, p.height);
        write_base64(f, p.data, p.size);
        fprintf(f, ")}\n");
        free(p.data);
    }
}

/* Writes the badge of a verdict, or of a submission's overall verdict. */
static void write_badge(FILE *f, const char *name, Tally tally)
{
    fprintf(f, "<span class=\"badge %s\">%s</span>", tally_class[tally], name);
}

/* Returns a submission's overall verdict: PASS when every scene passes, BUILD FAILED,
 * or FAIL; *tally gets its colour. */
static const char *overall_verdict(const Grading *g, const Submission *s, Tally *tally)
{
    if (s->build_message[0] != '\0') {
        *tally = TALLY_ERROR;
        return "BUILD FAILED";
    }
    if (s->tally[TALLY_PASS] == g->render_count) {
        *tally = TALLY_PASS;
        return "PASS";
    }
    *tally = TALLY_FAIL;
    return "FAIL";
}

/* Writes the page's head and title block: what was graded, how, when. */
static void write_heading(FILE *f, const Grading *g)
{
    fputs("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
          "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>",
          f);
    html_text(f, g->part);
    fputs(": grading report</title>\n<style>\n", f);
    write_style(f, g);
    fputs("</style>\n</head>\n<body>\n<header class=\"page\"><div>\n<h1>Grading report: part ", f);
    html_text(f, g->part);
    fprintf(f, "</h1>\n<p class=\"meta\">%d submission%s from <code>", g->sub_count,
            g->sub_count == 1 ? "" : "s");
    html_text(f, g->submissions);
    fprintf(f, "</code>, %d scene%s each, graded %s.</p>\n", g->render_count,
            g->render_count == 1 ? "" : "s", g->started);
    fputs("<p class=\"meta\">A pixel differs when one of its channels differs by more than ", f);
    html_text(f, g->threshold);
    fputs("; an image passes when at most the fraction ", f);
    html_text(f, g->allow);
    char limit[32];
    grade_size_text(g->memory_limit, limit, sizeof limit);
    fprintf(f,
            " of its pixels differ. A program gets %g s a scene and %g s to build; memory "
            "limit: %s.</p>\n",
            g->time_limit, g->build_time_limit, limit);
    if (g->illustrations != NULL) {
        fputs("<p class=\"meta\">Not graded (illustrations): ", f);
        html_text(f, g->illustrations);
        fputs(".</p>\n", f);
    }
    fputs("</div></header>\n<main>\n", f);
}

/* Writes the summary: a row a submission, linking to its details, and the legend. */
static void write_summary(FILE *f, const Grading *g)
{
    int passed = 0;
    for (int i = 0; i < g->sub_count; i++)
        passed += g->subs[i].tally[TALLY_PASS] == g->render_count;
    fprintf(f,
            "<section id=\"summary\">\n<h2>Summary</h2>\n<p class=\"counts\">%d of %d "
            "submission%s pass every scene.</p>\n",
            passed, g->sub_count, g->sub_count == 1 ? "" : "s");
    fputs("<table class=\"summary\">\n<thead><tr><th>Submission</th><th>Kind</th>"
          "<th class=\"n\">Pass</th><th class=\"n\">Fail</th><th class=\"n\">Missing</th>"
          "<th class=\"n\">Error</th><th>Scenes</th><th>Verdict</th></tr></thead>\n<tbody>\n",
          f);
    for (int i = 0; i < g->sub_count; i++) {
        const Submission *s = &g->subs[i];
        fprintf(f, "<tr><td><a href=\"#s%d\">", i + 1);
        html_text(f, s->name);
        fprintf(f, "</a></td><td>%s</td>", s->program ? "program" : "images");
        for (int t = 0; t < TALLY_COUNT; t++)
            fprintf(f, "<td class=\"n%s\">%d</td>", s->tally[t] == 0 ? " zero" : "", s->tally[t]);
        /* A square a scene, in its verdict's colour, named when pointed at. */
        fputs("<td class=\"dots\">", f);
        for (int k = 0; k < g->render_count; k++) {
            Verdict v = s->results[k].verdict;
            fprintf(f, "<span class=\"dot %s\" title=\"", tally_class[verdict_tally(v)]);
            html_text(f, g->renders[k].name);
            fprintf(f, ": %s\"></span>", verdict_name(v));
        }
        fputs("</td>", f);
        Tally tally;
        const char *verdict = overall_verdict(g, s, &tally);
        fputs("<td>", f);
        write_badge(f, verdict, tally);
        fputs("</td></tr>\n", f);
    }
    fputs("</tbody>\n</table>\n<details><summary>What the verdicts mean, and how they are "
          "counted</summary>\n<dl class=\"legend\">\n",
          f);
    for (int v = 0; v < VERDICT_COUNT; v++) {
        fputs("<dt>", f);
        write_badge(f, verdict_name((Verdict)v), verdict_tally((Verdict)v));
        fprintf(f, "</dt><dd>%s; counted as %s</dd>\n", meanings[v],
                tally_class[verdict_tally((Verdict)v)]);
    }
    fputs("</dl>\n</details>\n</section>\n", f);
}

/* Writes a block of a program's output, or nothing when there is none. */
static void write_log(FILE *f, const char *title, const char *log, bool open)
{
    if (log == NULL)
        return;
    fprintf(f, "<details class=\"log\"%s><summary>%s</summary><pre>", open ? " open" : "", title);
    html_text(f, log);
    fputs("</pre></details>\n", f);
}

/* One picture of a scene and how to show it. */
typedef struct {
    const char *path;    /* its thumbnail, or NULL */
    bool same;           /* show the reference's picture instead, with `classes` */
    const char *classes; /* "ref" for the reference itself, "black ref" for an empty heat map */
    const char *alt, *caption;
    const char *none; /* what the box says when there is no picture */
    double width;     /* the share of the column it fills: an image of another size than
                         the reference's is shown at its relative size */
} Shown;

/* Writes a figure of scene k: the thumbnail, the reference's picture, or a box of the
 * reference's shape saying that there is none. */
static void write_figure(FILE *f, const Shown *s, int k)
{
    Picture p;
    fputs("<figure>", f);
    if (s->same) {
        fprintf(f, "<div class=\"pic %s%d\" role=\"img\" aria-label=\"%s\"></div>", s->classes, k,
                s->alt);
    } else if (picture_read(s->path, &p)) {
        fprintf(f,
                "<img class=\"pic%s\" width=\"%d\" height=\"%d\" style=\"width:%.1f%%\" "
                "alt=\"%s\" src=\"data:image/png;base64,",
                p.width <= PIXELATED_WIDTH ? " px" : "", p.width, p.height, 100 * s->width, s->alt);
        write_base64(f, p.data, p.size);
        fputs("\">", f);
        free(p.data);
    } else {
        /* The reference's rule gives the box its shape; .pic.none wins its background. */
        fprintf(f, "<div class=\"pic none ref%d\">%s</div>", k, s->none);
    }
    fprintf(f, "<figcaption>%s</figcaption></figure>\n", s->caption);
}

/* Writes the table of imgdiff's figures. */
static void write_figures(FILE *f, const Figures *fig)
{
    fprintf(f,
            "<table class=\"figures\"><tr><th>Max diff R, G, B</th><td>%.3g, %.3g, %.3g /255</td>"
            "</tr>",
            fig->max[0] * 255, fig->max[1] * 255, fig->max[2] * 255);
    fprintf(f, "<tr><th>Mean abs diff</th><td>%.3g /255</td></tr>", fig->mean * 255);
    fprintf(f, "<tr><th>RMSE</th><td>%.4g</td></tr>", fig->rmse);
    if (isinf(fig->psnr))
        fputs("<tr><th>PSNR</th><td>&infin; (equal)</td></tr>", f);
    else
        fprintf(f, "<tr><th>PSNR</th><td>%.2f dB</td></tr>", fig->psnr);
    fprintf(f, "<tr><th>Differing pixels</th><td>%ld (%.3g%%)</td></tr>", fig->differing,
            fig->pixels > 0 ? 100.0 * fig->differing / fig->pixels : 0.0);
    if (fig->has_box)
        fprintf(f, "<tr><th>Region</th><td>(%d,%d)&ndash;(%d,%d)</td></tr>", fig->box[0],
                fig->box[1], fig->box[2], fig->box[3]);
    fputs("</table>\n", f);
}

/* Writes the pictures of a scene side by side, the reference, the submitted image and the
 * heat map, with imgdiff's figures. */
static void write_pictures(FILE *f, const SceneResult *res, int k)
{
    char caption[128] = "Differences";
    if (res->identical)
        snprintf(caption, sizeof caption, "Differences: none, the images are identical");
    else if (res->heat_show != NULL)
        snprintf(caption, sizeof caption, "Differences: black where equal, white at %.3g/255",
                 res->figures.heat_scale * 255);
    double width = res->relative_width > 0 && res->relative_width < 1 ? res->relative_width : 1;
    Shown shown[] = {
        {NULL, true, "ref", "reference image", "Reference", NULL, 1},
        {res->image_show, res->identical, "ref", "submitted image", "Submission", "no image",
         width},
        {res->heat_show, res->identical, "black ref", "heat map of the differences", caption,
         "no comparison", 1},
    };
    fputs("<div class=\"pictures\">\n", f);
    for (size_t i = 0; i < sizeof shown / sizeof shown[0]; i++)
        write_figure(f, &shown[i], k);
    if (res->compared)
        write_figures(f, &res->figures);
    fputs("</div>\n", f);
}

/* Writes one scene of one submission, a line that opens (open already unless it passed)
 * on the scene file, the pictures when there is an image, and the program's output. */
static void write_scene(FILE *f, const Grading *g, const Submission *s, int k)
{
    const Render *r = &g->renders[k];
    const SceneResult *res = &s->results[k];
    fprintf(f, "<details class=\"scene\"%s>\n<summary><span class=\"scene-name\">",
            res->verdict == VERDICT_PASS ? "" : " open");
    html_text(f, r->name);
    fputs("</span>", f);
    write_badge(f, verdict_name(res->verdict), verdict_tally(res->verdict));
    fputs("<span class=\"message\">", f);
    html_text(f, res->message);
    fputs("</span>", f);
    if (res->seconds >= 0)
        fprintf(f, "<span class=\"time\">%.2f s</span>", res->seconds);
    fputs("</summary>\n<div class=\"scene-body\">\n<p class=\"file\">Scene <code>", f);
    html_text(f, r->scene);
    for (char **a = r->args; *a != NULL; a++) {
        fputc(' ', f);
        html_text(f, *a);
    }
    fputs("</code></p>\n", f);
    if (res->identical || res->image_show != NULL)
        write_pictures(f, res, k);
    write_log(f, "Program output (the last lines)", res->log_tail,
              verdict_tally(res->verdict) == TALLY_ERROR);
    fputs("</div>\n</details>\n", f);
}

/* Writes one submission's section: its verdict, its build, and each of its scenes. */
static void write_submission(FILE *f, const Grading *g, int i)
{
    const Submission *s = &g->subs[i];
    Tally tally;
    const char *verdict = overall_verdict(g, s, &tally);
    fprintf(f, "<section id=\"s%d\">\n<h2><span class=\"name\">", i + 1);
    html_text(f, s->name);
    fprintf(f, "</span><span class=\"kind\">%s</span>", s->program ? "program" : "images");
    write_badge(f, verdict, tally);
    fputs("<a class=\"back\" href=\"#summary\">&uarr; summary</a></h2>\n", f);
    if (s->build_message[0] != '\0') {
        fputs("<div class=\"broken\"><strong>The build failed:</strong> ", f);
        html_text(f, s->build_message);
        fputs(". No scene could be rendered.", f);
        write_log(f, "Build output (the last lines)", s->build_log_tail, true);
        fputs("</div>\n</section>\n", f);
        return;
    }
    fprintf(f, "<p class=\"counts\">%d of %d scene%s pass.</p>\n", s->tally[TALLY_PASS],
            g->render_count, g->render_count == 1 ? "" : "s");
    write_log(f, "Build output (the last lines)", s->build_log_tail, false);
    for (int k = 0; k < g->render_count; k++)
        write_scene(f, g, s, k);
    fputs("</section>\n", f);
}

/* Writes the whole page. */
static void write_html(FILE *f, const Grading *g)
{
    write_heading(f, g);
    write_summary(f, g);
    for (int i = 0; i < g->sub_count; i++)
        write_submission(f, g, i);
    fputs("</main>\n<footer>Written by raytra's <code>tools/grade</code> (docs/grading.md). "
          "The builds, images, logs and heat maps are in <code>",
          f);
    html_text(f, g->work);
    fputs("</code>.</footer>\n</body>\n</html>\n", f);
}

/* Writes report.html to path; false (err) when it cannot. */
bool report_write_html(const Grading *g, const char *path, Error *err)
{
    return write_whole(path, write_html, g, err);
}
