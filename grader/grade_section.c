/* grade_section.c: a submission's section of the report: its points and lateness, its build, a block a scene with its pictures and output, scenes that failed alike in one. */
#include "grade_section.h"

#include <math.h>
#include <string.h>

#include "grade_base.h"
#include "grade_html.h"
#include "grade_late.h"
#include "grade_part.h"
#include "grade_run.h"
#include "grade_verdict.h"

/* A thumbnail this narrow or narrower is shown enlarged with sharp pixels. */
#define PIXELATED_WIDTH 200

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
    else if (html_picture_size(path, &w, &h)) {
        fprintf(f, "<img class=\"pic%s\" width=\"%d\" height=\"%d\" style=\"width:%.1f%%\" "
                   "alt=\"%s\" src=\"", w <= PIXELATED_WIDTH ? " px" : "", w, h, 100 * width, alt);
        html_put_picture(f, path);
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
char *section_command(const Submission *s, const SceneResult *res)
{
    char *run = grade_format("work/%s/run", strrchr(s->work, '/') + 1);
    return grade_format("cd %s && %s", run_quote(run), res->command);
}

/* Writes a block of a program's output, or nothing when there is none. */
static void write_log(FILE *f, const char *title, const char *log, bool open)
{
    if (log != NULL)
        fprintf(f, "<details class=\"log\"%s><summary>%s</summary><pre>%s</pre></details>\n",
                open ? " open" : "", title, html_escape(log));
}

/* Returns the first scene of submission s that did not pass with the same verdict and
 * reason as scene k, when at least one other did (a program that crashed the same way on
 * several scenes); -1 when scene k passed, or failed its own way. */
static int group_of(const Grading *g, const Submission *s, int k)
{
    const SceneResult *res = &s->results[k];
    int first = -1, count = 0;
    for (int j = 0; j < g->render_count && res->verdict != VERDICT_PASS; j++)
        if (s->results[j].verdict == res->verdict &&
            strcmp(s->results[j].message, res->message) == 0) {
            first = first < 0 ? j : first;
            count++;
        }
    return count >= 2 ? first : -1;
}

/* Writes the one open block of the scenes of s whose verdict and reason are scene k's
 * (group_of): "CRASHED on 8 scenes: a, b, c, ...: killed by signal 11", with the first
 * scene's command and output; each scene's own block follows, closed. */
static void write_group(FILE *f, const Grading *g, const Submission *s, int k)
{
    const SceneResult *res = &s->results[k];
    char *names = "";
    int count = 0;
    for (int j = k; j < g->render_count; j++)
        if (group_of(g, s, j) == k) {
            names = grade_format("%s%s%s%s", names, count > 0 ? ", " : "",
                                 html_escape(g->renders[j].name),
                                 g->renders[j].hidden ? " (hidden)" : "");
            count++;
        }
    fprintf(f, "<details class=\"scene\" open>\n<summary>%s<span class=\"message\">on %d "
               "scenes: %s: %s</span></summary>\n<div class=\"scene-body\">\n<p class=\"file\">"
               "The same verdict and reason on each of these scenes; their blocks below are "
               "closed. The first, %s:</p>\n",
            html_badge(g, s, k), count, names, html_escape(res->message),
            html_escape(g->renders[k].name));
    if (res->command != NULL)
        fprintf(f, "<p class=\"file\">Command <code>%s</code></p>\n",
                html_escape(section_command(s, res)));
    write_log(f, "Program output (the last lines)",
              res->command != NULL && res->log_tail == NULL ? "(nothing)" : res->log_tail,
              verdict_info[res->verdict].tally == TALLY_ERROR);
    fputs("</div>\n</details>\n", f);
}

/* Writes scene k of submission s: a line that opens (open already when `open`) on the scene
 * file, the command run, the pictures when there is an image, and the program's output. */
static void write_scene(FILE *f, const Grading *g, const Submission *s, int k, bool open)
{
    const Render *r = &g->renders[k];
    const SceneResult *res = &s->results[k];
    fprintf(f,
            "<details class=\"scene\"%s>\n<summary><span class=\"scene-name\">%s</span>"
            "%s%s<span class=\"message\">%s</span>%s</summary>\n<div class=\"scene-body\">"
            "\n<p class=\"file\">Scene <code>%s",
            open ? " open" : "",
            r->hidden ? grade_format("%s (hidden)", html_escape(r->name)) : html_escape(r->name),
            html_badge(g, s, k), html_copy_flag(res->copy), html_escape(res->message),
            res->seconds > 0 ? grade_format("<span class=\"time\">%.2f s</span>", res->seconds)
                             : "",
            html_escape(r->scene));
    for (char **a = r->argv + RENDER_WORDS; *a != NULL; a++)
        fprintf(f, " %s", html_escape(*a));
    fputs("</code></p>\n", f);
    /* What was run, where (from the report's folder), to run it again by hand. */
    if (res->command != NULL)
        fprintf(f, "<p class=\"file\">Command <code>%s</code></p>\n",
                html_escape(section_command(s, res)));
    if (res->compared || res->relative_width > 0)
        write_pictures(f, res, k, r->statistical);
    write_log(f, "Program output (the last lines)",
              res->command != NULL && res->log_tail == NULL ? "(nothing)" : res->log_tail,
              open && verdict_info[res->verdict].tally == TALLY_ERROR);
    fputs("</div>\n</details>\n", f);
}

/* Writes the section of submission i: its verdict, its points, when it was handed in, its
 * build, and a block a scene: open when it did not pass, but for scenes that failed alike,
 * which one open block stands for (write_group). */
void section_write(FILE *f, const Grading *g, int i)
{
    const Submission *s = &g->subs[i];
    bool broken = s->build_message != NULL;
    char *late = late_describe(g, s);
    fprintf(f, "<section id=\"s%d\">\n<h2><span class=\"name\">%s</span><span class=\"kind\">"
               "%s</span>%s<a class=\"back\" href=\"#summary\">&uarr; summary</a></h2>\n",
            i + 1, html_escape(s->name), s->program ? "program" : "images",
            html_badge(g, s, -1));
    if (broken)
        fprintf(f, "<div class=\"broken\"><strong>The build failed:</strong> %s. No scene "
                   "could be rendered.", html_escape(s->build_message));
    else {
        double max, got = part_points(g, s, &max);
        fprintf(f, "<p class=\"counts\">%d of %d scene%s pass: %g of %g points.</p>\n",
                s->tally[TALLY_PASS], g->render_count, html_plural(g->render_count), got, max);
    }
    if (late != NULL)
        fprintf(f, "<p class=\"counts\">%s</p>\n", html_escape(late));
    if (s->removed != NULL)
        fprintf(f, "<p class=\"file\">Build outputs it carried, removed before make: "
                   "<code>%s</code></p>\n", html_escape(s->removed));
    write_log(f, "Build output (the last lines)", s->build_log_tail, broken);
    for (int k = 0; k < g->render_count && !broken; k++) {
        int group = group_of(g, s, k);
        if (group == k)
            write_group(f, g, s, k);
        write_scene(f, g, s, k, group < 0 && s->results[k].verdict != VERDICT_PASS);
    }
    fputs(broken ? "</div>\n</section>\n" : "</section>\n", f);
}
