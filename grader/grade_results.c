/* grade_results.c: a submission's results as words of a results file (a shard's, a worker's), written and read. */
#include "grade_results.h"

#include <stdlib.h>
#include <string.h>

#include "grade_base.h"
#include "grade_path.h"
#include "grade_verdict.h"

/* Writes a text as one word of a results file: '=' and its bytes, '%' and the bytes up to
 * the space and DEL written %XX; a lone '-' for NULL. */
void results_put_text(FILE *f, const char *text)
{
    fputs(text == NULL ? " -" : " =", f);
    for (const unsigned char *t = (const unsigned char *)text; t != NULL && *t != '\0'; t++)
        fprintf(f, *t <= ' ' || *t == '%' || *t == 0x7F ? "%%%02X" : "%c", *t);
}

/* Writes a path below the work folder `work` as one word, relative to it. */
static void put_path(FILE *f, const char *work, const char *path)
{
    size_t len = strlen(work);
    results_put_text(f, path != NULL && strncmp(path, work, len) == 0 ? path + len + 1 : path);
}

/* Writes submission s of g: a "sub" line (with when it was handed in), then a "scene" line
 * a render, the figures exactly (%a), every path relative to the work folder. */
void results_put_submission(FILE *f, const Grading *g, const Submission *s)
{
    fputs("sub", f);
    put_path(f, g->work, s->work);
    results_put_text(f, s->name);
    results_put_text(f, s->path);
    fprintf(f, " %d", s->program);
    results_put_text(f, s->link);
    results_put_text(f, s->build_message);
    results_put_text(f, s->build_log_tail);
    results_put_text(f, s->removed);
    fprintf(f, " %a", s->submitted);
    results_put_text(f, s->time_source);
    fputc('\n', f);
    for (int k = 0; k < g->render_count; k++) {
        const SceneResult *r = &s->results[k];
        const Figures *x = &r->figures;
        fprintf(f, "scene %d", (int)r->verdict);
        results_put_text(f, r->message);
        fprintf(f, " %d %d %d %a %a", r->compared, r->identical, r->copy, r->relative_width,
                r->seconds);
        put_path(f, g->work, r->image_show);
        put_path(f, g->work, r->heat_show);
        results_put_text(f, r->log_tail);
        results_put_text(f, r->command);
        fprintf(f, " %a %a %a %a %a %a %a %a %ld %ld %d %d %d %d %a", x->threshold, x->allow,
                x->max[0], x->max[1], x->max[2], x->mean, x->rmse, x->psnr, x->differing, x->pixels,
                x->box[0], x->box[1], x->box[2], x->box[3], x->heat_scale);
        fprintf(f, " %a %a %a %a %a %ld\n", x->bias_z, x->bias_critical, x->noise, x->noise_low,
                x->noise_high, x->exact);
    }
}

/* Reads the next line into r's words; false at the end of the file. */
bool results_next_line(Reader *r)
{
    if (getline(&r->text, &r->size, r->file) < 0)
        return false;
    r->line++;
    r->raw = grade_format("%s", r->text);
    r->count = 0;
    for (char *w = strtok(r->text, " \n"); w != NULL && r->count < 64; w = strtok(NULL, " \n"))
        r->word[r->count++] = w;
    return true;
}

/* Tells whether the line read is `key` with `count` words after it. */
bool results_line_is(const Reader *r, const char *key, int count)
{
    return r->count == count + 1 && strcmp(r->word[0], key) == 0;
}

/* Returns word k of the line as text (NULL for '-'), its %XX undone; marks r bad when it is
 * not a text word. */
char *results_get_text(Reader *r, int k)
{
    const char *w = r->word[k];
    if (w[0] == '-' && w[1] == '\0')
        return NULL;
    char *out = grade_alloc(strlen(w) + 1), *o = out;
    unsigned byte;
    r->bad |= w[0] != '=';
    for (const char *p = w + 1; *p != '\0' && !r->bad; p++)
        if (*p != '%')
            *o++ = *p;
        else if (sscanf(p + 1, "%2x", &byte) == 1 && byte > 0 && p[1] != '\0' && p[2] != '\0')
            *o++ = (char)byte, p += 2;
        else
            r->bad = true;
    return out;
}

/* Returns word k of the line as text that must be there; marks r bad when it is not. */
char *results_get_word(Reader *r, int k)
{
    char *text = results_get_text(r, k);
    r->bad |= text == NULL;
    return text != NULL ? text : "";
}

/* Returns word k of the line as a number; marks r bad when it is not one. */
double results_get_number(Reader *r, int k)
{
    char *end;
    double v = strtod(r->word[k], &end);
    r->bad |= end == r->word[k] || *end != '\0';
    return v;
}

/* Returns word k as a path below the work folder `work` (NULL stays NULL). */
static char *get_path(Reader *r, int k, const char *work)
{
    char *p = results_get_text(r, k);
    return p == NULL ? NULL : grade_format("%s/%s", work, p);
}

/* Reads a submission's lines, whose "sub" line has been read, into s; its pictures are found
 * below the work folder `work`, its work folder is named below `work_name`. False (reported)
 * when the file is not as results_put_submission writes it. */
bool results_get_submission(Reader *r, const Grading *g, Submission *s, const char *work,
                            const char *work_name)
{
    if (!results_line_is(r, "sub", 10))
        return grade_fail("%s:%d: expected a submission", r->path, r->line);
    *s = (Submission){.work = get_path(r, 1, work_name),
                      .name = results_get_word(r, 2),
                      .path = results_get_word(r, 3),
                      .program = results_get_number(r, 4) != 0,
                      .link = results_get_text(r, 5),
                      .build_message = results_get_text(r, 6),
                      .build_log_tail = results_get_text(r, 7),
                      .removed = results_get_text(r, 8),
                      .submitted = results_get_number(r, 9)};
    /* Where the time came from: one of handin_find_all's words, or none. */
    static const char *const sources[] = {"git", "files", "given"};
    char *source = results_get_text(r, 10);
    for (size_t k = 0; source != NULL && k < sizeof sources / sizeof sources[0]; k++)
        if (strcmp(source, sources[k]) == 0)
            s->time_source = sources[k];
    r->bad |= source != NULL && s->time_source == NULL;
    s->results = grade_alloc((size_t)g->render_count * sizeof *s->results);
    for (int k = 0; k < g->render_count && !r->bad; k++) {
        SceneResult *x = &s->results[k];
        Figures *f = &x->figures;
        if (!results_next_line(r) || !results_line_is(r, "scene", 32))
            return grade_fail("%s:%d: expected scene %d of %s", r->path, r->line, k + 1, s->name);
        double v = results_get_number(r, 1);
        r->bad |= !(v >= 0 && v < VERDICT_COUNT) || s->work == NULL;
        x->verdict = r->bad ? VERDICT_ERROR : (Verdict)v;
        snprintf(x->message, sizeof x->message, "%s", results_get_word(r, 2));
        x->compared = results_get_number(r, 3) != 0;
        x->identical = results_get_number(r, 4) != 0;
        x->copy = results_get_number(r, 5) != 0;
        x->relative_width = results_get_number(r, 6);
        x->seconds = results_get_number(r, 7);
        x->image_show = get_path(r, 8, work);
        x->heat_show = get_path(r, 9, work);
        x->log_tail = results_get_text(r, 10);
        x->command = results_get_text(r, 11);
        double *numbers[] = {&f->threshold, &f->allow, f->max,   f->max + 1,
                             f->max + 2,    &f->mean,  &f->rmse, &f->psnr};
        for (int n = 0; n < 8; n++)
            *numbers[n] = results_get_number(r, 12 + n);
        f->differing = (long)results_get_number(r, 20);
        f->pixels = (long)results_get_number(r, 21);
        for (int n = 0; n < 4; n++)
            f->box[n] = (int)results_get_number(r, 22 + n);
        f->heat_scale = results_get_number(r, 26);
        double *statistics[] = {&f->bias_z, &f->bias_critical, &f->noise, &f->noise_low,
                                &f->noise_high};
        for (int n = 0; n < 5; n++)
            *statistics[n] = results_get_number(r, 27 + n);
        f->exact = (long)results_get_number(r, 32);
        s->tally[verdict_info[x->verdict].tally]++;
    }
    return !r->bad || grade_fail("%s:%d: a word is not as grade writes it", r->path, r->line);
}

/* Reads the results file at path, written by a worker of --jobs, into submission s; returns
 * the progress it told, or NULL (reported) when the file is not whole. */
char *results_read_submission(const Grading *g, Submission *s, const char *path)
{
    const char *kind;
    Reader r = {.file = path_open_regular(path, &kind), .path = path};
    char *told = NULL;
    if (r.file == NULL)
        return NULL;
    if (results_next_line(&r) && results_get_submission(&r, g, s, g->work, g->work) &&
        results_next_line(&r) && results_line_is(&r, "told", 1))
        told = results_get_text(&r, 1);
    free(r.text);
    fclose(r.file);
    return r.bad ? NULL : told;
}
