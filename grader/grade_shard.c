/* grade_shard.c: a class in slices (--shard K/N), and the results files of shards and workers. */
#include "grade.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "imgfile.h"
#include "outfile.h"
#include "toolopt.h"

/* The first line of a results file, with the version of its format. */
#define RESULTS_MAGIC "grade-results 4"

/* Reads --shard K/N into g and checks what goes with it; false (reported) when it cannot. */
bool shard_parse(Grading *g)
{
    int n = 0;
    if (g->shard == NULL)
        return true;
    if (sscanf(g->shard, "%d/%d%n", &g->shard_k, &g->shard_n, &n) != 2 || g->shard[n] != '\0' ||
        g->shard_n < 1 || g->shard_n > 10000 || g->shard_k < 1 || g->shard_k > g->shard_n)
        return grade_fail("--shard takes K/N, the K-th of N slices, 1 <= K <= N <= 10000; got "
                          "'%s'",
                          g->shard);
    if (g->self || g->junit != NULL || g->gradescope != NULL)
        return g->self ? grade_fail("--shard cannot go with --self: a shard is a slice of a class")
                       : grade_fail("--shard cannot go with --junit or --gradescope: give "
                                    "--junit to grade merge, which writes the class's verdicts");
    if (g->out == NULL)
        g->out = grade_format("grading-%s-shard-%d-of-%d", g->part, g->shard_k, g->shard_n);
    return true;
}

/* Keeps in g->subs the shard's slice of the class, every N-th submission from the K-th (a
 * slice that does not depend on what other shards find), after noting the whole class's
 * names in g->members. Without --shard, the class is its own slice. */
void shard_select(Grading *g)
{
    g->members = grade_alloc((size_t)g->sub_count * sizeof *g->members);
    g->member_count = g->sub_count;
    int kept = 0;
    for (int k = 0; k < g->sub_count; k++) {
        g->members[k] = g->subs[k].name;
        if (g->shard_n == 0 || k % g->shard_n == g->shard_k - 1)
            g->subs[kept++] = g->subs[k];
    }
    g->sub_count = kept;
}

/* Writes a text as one word of a results file: '=' and its bytes, '%' and the bytes up to
 * the space and DEL written %XX; a lone '-' for NULL. */
void shard_put_text(FILE *f, const char *text)
{
    fputs(text == NULL ? " -" : " =", f);
    for (const unsigned char *t = (const unsigned char *)text; t != NULL && *t != '\0'; t++)
        fprintf(f, *t <= ' ' || *t == '%' || *t == 0x7F ? "%%%02X" : "%c", *t);
}

/* Writes a path below the work folder `work` as one word, relative to it. */
static void put_path(FILE *f, const char *work, const char *path)
{
    size_t len = strlen(work);
    shard_put_text(f, path != NULL && strncmp(path, work, len) == 0 ? path + len + 1 : path);
}

/* Writes submission s of g: a "sub" line, then a "scene" line a render, the figures exactly
 * (%a), every path relative to the work folder. */
void shard_put_submission(FILE *f, const Grading *g, const Submission *s)
{
    fputs("sub", f);
    put_path(f, g->work, s->work);
    shard_put_text(f, s->name);
    shard_put_text(f, s->path);
    fprintf(f, " %d", s->program);
    shard_put_text(f, s->link);
    shard_put_text(f, s->build_message);
    shard_put_text(f, s->build_log_tail);
    shard_put_text(f, s->removed);
    fputc('\n', f);
    for (int k = 0; k < g->render_count; k++) {
        const SceneResult *r = &s->results[k];
        const Figures *x = &r->figures;
        fprintf(f, "scene %d", (int)r->verdict);
        shard_put_text(f, r->message);
        fprintf(f, " %d %d %d %a %a", r->compared, r->identical, r->copy, r->relative_width,
                r->seconds);
        put_path(f, g->work, r->image_show);
        put_path(f, g->work, r->heat_show);
        shard_put_text(f, r->log_tail);
        shard_put_text(f, r->command);
        fprintf(f, " %a %a %a %a %a %a %a %a %ld %ld %d %d %d %d %a", x->threshold, x->allow,
                x->max[0], x->max[1], x->max[2], x->mean, x->rmse, x->psnr, x->differing, x->pixels,
                x->box[0], x->box[1], x->box[2], x->box[3], x->heat_scale);
        fprintf(f, " %a %a %a %a %a %ld\n", x->bias_z, x->bias_critical, x->noise, x->noise_low,
                x->noise_high, x->exact);
    }
}

/* A results file being read, a line at a time, split into words. */
typedef struct {
    FILE *file;
    const char *path;
    int line;
    char *text;
    size_t size;
    char *raw; /* the line as it was, before it was split */
    char *word[64];
    int count;
    bool bad; /* a word was not as expected */
} Reader;

/* Reads the next line into r's words; false at the end of the file. */
static bool next_line(Reader *r)
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
static bool line_is(const Reader *r, const char *key, int count)
{
    return r->count == count + 1 && strcmp(r->word[0], key) == 0;
}

/* Returns word k of the line as text (NULL for '-'), its %XX undone; marks r bad when it is
 * not a text word. */
static char *get_text(Reader *r, int k)
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
static char *get_word(Reader *r, int k)
{
    char *text = get_text(r, k);
    r->bad |= text == NULL;
    return text != NULL ? text : "";
}

/* Returns word k of the line as a number; marks r bad when it is not one. */
static double get_number(Reader *r, int k)
{
    char *end;
    double v = strtod(r->word[k], &end);
    r->bad |= end == r->word[k] || *end != '\0';
    return v;
}

/* Returns word k as a path below the work folder `work` (NULL stays NULL). */
static char *get_path(Reader *r, int k, const char *work)
{
    char *p = get_text(r, k);
    return p == NULL ? NULL : grade_format("%s/%s", work, p);
}

/* Reads a submission's lines, whose "sub" line has been read, into s; its pictures are found
 * below the work folder `work`, its work folder is named below `work_name`. False (reported)
 * when the file is not as shard_put_submission writes it. */
static bool get_submission(Reader *r, const Grading *g, Submission *s, const char *work,
                           const char *work_name)
{
    if (!line_is(r, "sub", 8))
        return grade_fail("%s:%d: expected a submission", r->path, r->line);
    *s = (Submission){.work = get_path(r, 1, work_name),
                      .name = get_word(r, 2),
                      .path = get_word(r, 3),
                      .program = get_number(r, 4) != 0,
                      .link = get_text(r, 5),
                      .build_message = get_text(r, 6),
                      .build_log_tail = get_text(r, 7),
                      .removed = get_text(r, 8)};
    s->results = grade_alloc((size_t)g->render_count * sizeof *s->results);
    for (int k = 0; k < g->render_count && !r->bad; k++) {
        SceneResult *x = &s->results[k];
        Figures *f = &x->figures;
        if (!next_line(r) || !line_is(r, "scene", 32))
            return grade_fail("%s:%d: expected scene %d of %s", r->path, r->line, k + 1, s->name);
        double v = get_number(r, 1);
        r->bad |= !(v >= 0 && v < VERDICT_COUNT) || s->work == NULL;
        x->verdict = r->bad ? VERDICT_ERROR : (Verdict)v;
        snprintf(x->message, sizeof x->message, "%s", get_word(r, 2));
        x->compared = get_number(r, 3) != 0;
        x->identical = get_number(r, 4) != 0;
        x->copy = get_number(r, 5) != 0;
        x->relative_width = get_number(r, 6);
        x->seconds = get_number(r, 7);
        x->image_show = get_path(r, 8, work);
        x->heat_show = get_path(r, 9, work);
        x->log_tail = get_text(r, 10);
        x->command = get_text(r, 11);
        double *numbers[] = {&f->threshold, &f->allow, f->max,   f->max + 1,
                             f->max + 2,    &f->mean,  &f->rmse, &f->psnr};
        for (int n = 0; n < 8; n++)
            *numbers[n] = get_number(r, 12 + n);
        f->differing = (long)get_number(r, 20);
        f->pixels = (long)get_number(r, 21);
        for (int n = 0; n < 4; n++)
            f->box[n] = (int)get_number(r, 22 + n);
        f->heat_scale = get_number(r, 26);
        double *statistics[] = {&f->bias_z, &f->bias_critical, &f->noise, &f->noise_low,
                                &f->noise_high};
        for (int n = 0; n < 5; n++)
            *statistics[n] = get_number(r, 27 + n);
        f->exact = (long)get_number(r, 32);
        s->tally[verdict_info[x->verdict].tally]++;
    }
    return !r->bad || grade_fail("%s:%d: a word is not as grade writes it", r->path, r->line);
}

/* Opens the file at path to read when it is a regular file, never blocking on a FIFO nor
 * following a symbolic link; NULL when it cannot, with *kind the file's kind in words when
 * it is there but not a regular file, else NULL (errno says why). */
static FILE *open_regular(const char *path, const char **kind)
{
    struct stat st;
    *kind = NULL;
    if (lstat(path, &st) == 0 && !S_ISREG(st.st_mode)) {
        *kind = imgfile_kind_text(st.st_mode);
        return NULL;
    }
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOFOLLOW | O_CLOEXEC), flags;
    bool opened = fd >= 0 && fstat(fd, &st) == 0;
    FILE *f = NULL;
    /* Checked again on the descriptor: the path may have changed since lstat. */
    if (opened && !S_ISREG(st.st_mode))
        *kind = imgfile_kind_text(st.st_mode);
    else if (opened && (flags = fcntl(fd, F_GETFL)) >= 0 &&
             fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) == 0)
        f = fdopen(fd, "r");
    if (fd >= 0 && f == NULL)
        close(fd);
    return f;
}

/* Reads the results file at path, written by a worker of --jobs, into submission s; returns
 * the progress it told, or NULL (reported) when the file is not whole. */
char *shard_read_submission(const Grading *g, Submission *s, const char *path)
{
    const char *kind;
    Reader r = {.file = open_regular(path, &kind), .path = path};
    char *told = NULL;
    if (r.file == NULL)
        return NULL;
    if (next_line(&r) && get_submission(&r, g, s, g->work, g->work) && next_line(&r) &&
        line_is(&r, "told", 1))
        told = get_text(&r, 1);
    free(r.text);
    fclose(r.file);
    return r.bad ? NULL : told;
}

/* Returns a fingerprint of the file at path, its bytes' FNV-1a hash in hex; "none" when it
 * cannot be read. Shards graded against references that differ have different ones. */
static char *fingerprint(const char *path)
{
    FILE *f = fopen(path, "rb");
    uint64_t hash = 0xcbf29ce484222325u;
    for (int c; f != NULL && (c = getc(f)) != EOF;)
        hash = (hash ^ (uint64_t)c) * 0x100000001b3u;
    if (f == NULL)
        return "none";
    fclose(f);
    return grade_format("%016llx", (unsigned long long)hash);
}

/* Writes what a shard's results were made from, line by line: what merge checks to be the
 * same in every shard, the shard's own number after it. */
static void put_heading(FILE *f, const Grading *g)
{
    fprintf(f, RESULTS_MAGIC "\npart");
    shard_put_text(f, g->part);
    fputs("\nsubmissions", f);
    shard_put_text(f, g->submissions);
    fputs("\ntolerances", f);
    shard_put_text(f, g->threshold);
    shard_put_text(f, g->allow);
    shard_put_text(f, g->standard);
    fprintf(f, "\nlimits %a %a %lld\npoints %a\nillustrations", g->time_limit,
            g->build_time_limit, g->memory_limit, g->part_points);
    shard_put_text(f, g->illustrations);
    fprintf(f, "\nrenders %d\n", g->render_count);
    for (int k = 0; k < g->render_count; k++) {
        const Render *r = &g->renders[k];
        fputs("render", f);
        shard_put_text(f, r->image);
        shard_put_text(f, r->name);
        shard_put_text(f, r->scene);
        /* How the image is judged, too: a shard graded otherwise is not the same grading. */
        char *print = fingerprint(r->reference);
        shard_put_text(f, r->judge == JUDGE_COVER
                              ? grade_format("%s>%s", print, fingerprint(r->mask))
                          : r->judge == JUDGE_SAME_AS ? grade_format("%s=%d", print, r->same_as)
                                                      : print);
        fprintf(f, " %a %d %d", r->points, r->hidden, r->statistical);
        shard_put_text(f, r->visibility);
        for (char **a = r->argv + RENDER_WORDS; *a != NULL; a++)
            shard_put_text(f, *a);
        fputc('\n', f);
    }
    fprintf(f, "class %d\n", g->member_count);
    for (int k = 0; k < g->member_count; k++) {
        fputs("member", f);
        shard_put_text(f, g->members[k]);
        fputc('\n', f);
    }
    fprintf(f, "shard %d %d\nstarted", g->shard_k, g->shard_n);
    shard_put_text(f, g->started);
    shard_put_text(f, g->sandbox);
    fprintf(f, "\nsubmissions %d\n", g->sub_count);
}

/* Writes OUT/shard.txt: the heading, every submission of the slice, and "end"; whole or not
 * at all (outfile); false (reported) when it cannot. */
bool shard_write(const Grading *g)
{
    char *path = grade_format("%s/shard.txt", g->out);
    OutFile out;
    Error err;
    bool ok = outfile_open(&out, path, &err);
    if (ok) {
        put_heading(out.file, g);
        for (int k = 0; k < g->sub_count; k++)
            shard_put_submission(out.file, g, &g->subs[k]);
        fputs("end\n", out.file);
    }
    if (!(ok && outfile_commit(&out, &err)))
        return grade_fail("cannot write %s: %s", path, err.text);
    fprintf(g->progress, "grade: wrote %s, shard %d of %d (grade merge makes the report)\n", path,
            g->shard_k, g->shard_n);
    return true;
}

/* Reads the heading's lines that every shard must share into g, and their text into
 * g->heading; false (reported) when they are not as put_heading writes them. */
static bool get_heading(Reader *r, Grading *g, const char *work)
{
    char *heading = "";
    int renders = -1, members = -1;
    for (int line = 0; (members < 0 || line < 8 + renders + members) && next_line(r); line++) {
        heading = grade_format("%s%s", heading, r->raw);
        if (line == 0 && line_is(r, "part", 1))
            g->part = get_word(r, 1);
        else if (line == 1 && line_is(r, "submissions", 1))
            g->submissions = get_word(r, 1);
        else if (line == 2 && line_is(r, "tolerances", 3))
            g->threshold = get_word(r, 1), g->allow = get_word(r, 2), g->standard = get_text(r, 3);
        else if (line == 3 && line_is(r, "limits", 3))
            g->time_limit = get_number(r, 1), g->build_time_limit = get_number(r, 2),
            g->memory_limit = (long long)get_number(r, 3);
        else if (line == 4 && line_is(r, "points", 1))
            g->part_points = get_number(r, 1);
        else if (line == 5 && line_is(r, "illustrations", 1))
            g->illustrations = get_text(r, 1);
        else if (line == 6 && line_is(r, "renders", 1) && (renders = (int)get_number(r, 1)) > 0 &&
                 renders < 100000)
            g->renders = grade_alloc((size_t)renders * sizeof *g->renders);
        else if (line > 6 && line <= 6 + renders && r->count >= 9 &&
                 line_is(r, "render", r->count - 1)) {
            Render *x = &g->renders[g->render_count++];
            *x = (Render){.image = get_word(r, 1), .name = get_word(r, 2), .scene = get_word(r, 3),
                          .points = get_number(r, 5), .hidden = get_number(r, 6) != 0,
                          .statistical = get_number(r, 7) != 0, .visibility = get_word(r, 8)};
            x->argv = grade_alloc((size_t)(r->count - 9 + RENDER_WORDS + 1) * sizeof *x->argv);
            for (int k = 9; k < r->count; k++)
                x->argv[RENDER_WORDS + k - 9] = get_word(r, k);
            x->reference_show = grade_format("%s/references/%s.png", work, x->name);
        } else if (line == 7 + renders && line_is(r, "class", 1) &&
                   (members = (int)get_number(r, 1)) >= 0 && members < 1000000)
            g->members = grade_alloc(((size_t)members + 1) * sizeof *g->members);
        else if (line > 7 + renders && line <= 7 + renders + members && line_is(r, "member", 1))
            g->members[g->member_count++] = get_word(r, 1);
        else
            r->bad = true;
        if (r->bad)
            return grade_fail("%s:%d: not a line of what grade --shard writes", r->path, r->line);
    }
    g->heading = heading;
    return members >= 0 || grade_fail("%s: cut short after line %d", r->path, r->line);
}

/* Reads the shard in `folder` (FOLDER/shard.txt, written by grade --shard) into g, its
 * pictures found in FOLDER/work; false (reported) when there is none, or it is not whole. */
bool shard_read(Grading *g, const char *folder)
{
    char real[PATH_MAX];
    const char *kind;
    Reader r = {.path = grade_format("%s/shard.txt", folder)};
    if (realpath(folder, real) == NULL || path_kind(real) != S_IFDIR)
        return grade_fail("no shard folder %s", folder);
    if ((r.file = open_regular(r.path, &kind)) == NULL && kind != NULL)
        return grade_fail("%s is not a regular file (%s): not the results of grade --shard",
                          r.path, kind);
    if (r.file == NULL)
        return grade_fail("no %s: %s is not a folder of grade --shard, or its grading did not "
                          "finish (its log says why)",
                          r.path, folder);
    g->out = folder;
    g->work = grade_format("%s/work", real);
    int count = -1;
    bool ok = (next_line(&r) && strcmp(r.raw, RESULTS_MAGIC "\n") == 0) ||
              grade_fail("%s is not a results file of this grade", r.path);
    ok = ok && get_heading(&r, g, g->work) && next_line(&r) && line_is(&r, "shard", 2);
    g->shard_k = ok ? (int)get_number(&r, 1) : 0;
    g->shard_n = ok ? (int)get_number(&r, 2) : 0;
    ok = ok && g->shard_n >= 1 && g->shard_n <= 10000 && g->shard_k >= 1 &&
         g->shard_k <= g->shard_n && next_line(&r) && line_is(&r, "started", 2) &&
         snprintf(g->started, sizeof g->started, "%s", get_word(&r, 1)) >= 0 &&
         ((g->sandbox = get_text(&r, 2)), next_line(&r)) &&
         line_is(&r, "submissions", 1) && (count = (int)get_number(&r, 1)) >= 0 &&
         count <= g->member_count && !r.bad;
    g->subs = grade_alloc(((size_t)count + 1) * sizeof *g->subs);
    while (ok && g->sub_count < count && next_line(&r))
        ok = get_submission(&r, g, &g->subs[g->sub_count++], g->work, g->work);
    ok = ok && next_line(&r) && strcmp(r.raw, "end\n") == 0;
    if (!ok && !r.bad)
        grade_fail("%s:%d: the file is not whole", r.path, r.line);
    free(r.text);
    fclose(r.file);
    return ok;
}
