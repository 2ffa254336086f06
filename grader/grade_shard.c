/* grade_shard.c: a class in slices (--shard K/N): a shard's slice, its shard.txt written and read back for merge. */
#include "grade_shard.h"

#include <limits.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "grade_base.h"
#include "grade_path.h"
#include "grade_results.h"
#include "outfile.h"

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

/* Writes what a grading's results were made from, line by line, from its part to its
 * class's last member: what merge checks to be the same in every shard, and --only in a
 * class's earlier grading. */
static void put_grading(FILE *f, const Grading *g)
{
    fputs("part", f);
    results_put_text(f, g->part);
    fputs("\nsubmissions", f);
    results_put_text(f, g->submissions);
    fputs("\ntolerances", f);
    results_put_text(f, g->threshold);
    results_put_text(f, g->allow);
    results_put_text(f, g->standard);
    const LatePolicy *l = &g->late;
    fprintf(f, "\nlimits %a %a %lld\npoints %a %d %a %d %a %a %d %a %d %d %d %a\nillustrations",
            g->time_limit, g->build_time_limit, g->memory_limit, g->part_points, l->due_set,
            l->due, l->zone, l->grace, l->per_day, l->cap_set, l->cap, l->max_days_set,
            l->max_days, l->until_set, l->until);
    results_put_text(f, g->illustrations);
    fprintf(f, "\nrenders %d\n", g->render_count);
    for (int k = 0; k < g->render_count; k++) {
        const Render *r = &g->renders[k];
        fputs("render", f);
        results_put_text(f, r->image);
        results_put_text(f, r->name);
        results_put_text(f, r->scene);
        /* How the image is judged, too: a shard graded otherwise is not the same grading. */
        char *print = fingerprint(r->reference);
        results_put_text(f, r->judge == JUDGE_COVER
                              ? grade_format("%s>%s", print, fingerprint(r->mask))
                          : r->judge == JUDGE_SAME_AS ? grade_format("%s=%d", print, r->same_as)
                                                      : print);
        fprintf(f, " %a %d %d", r->points, r->hidden, r->statistical);
        results_put_text(f, r->visibility);
        for (char **a = r->argv + RENDER_WORDS; *a != NULL; a++)
            results_put_text(f, *a);
        fputc('\n', f);
    }
    fprintf(f, "class %d\n", g->member_count);
    for (int k = 0; k < g->member_count; k++) {
        fputs("member", f);
        results_put_text(f, g->members[k]);
        fputc('\n', f);
    }
}

/* Writes the heading of a results file: its first line, what the grading was made from (a
 * merge's as its shards had it: their references are not read again), the shard's number
 * and what else it tells. */
static void put_heading(FILE *f, const Grading *g)
{
    fputs(RESULTS_MAGIC "\n", f);
    if (g->heading != NULL)
        fputs(g->heading, f);
    else
        put_grading(f, g);
    /* A whole class's results (results.txt) are its one shard. */
    fprintf(f, "shard %d %d\nstarted", g->shard_n > 0 ? g->shard_k : 1,
            g->shard_n > 0 ? g->shard_n : 1);
    results_put_text(f, g->started);
    results_put_text(f, g->sandbox);
    fprintf(f, "\nsubmissions %d\n", g->sub_count);
}

/* Writes OUT/shard.txt, or for a whole class OUT/results.txt (what --only reads): the
 * heading, every submission of the slice, and "end"; whole or not at all (outfile); false
 * (reported) when it cannot. */
bool shard_write(const Grading *g)
{
    char *path = grade_format("%s/%s", g->out, g->shard_n > 0 ? "shard.txt" : "results.txt");
    OutFile out;
    Error err;
    bool ok = outfile_open(&out, path, &err);
    if (ok) {
        put_heading(out.file, g);
        for (int k = 0; k < g->sub_count; k++)
            results_put_submission(out.file, g, &g->subs[k]);
        fputs("end\n", out.file);
    }
    if (!(ok && outfile_commit(&out, &err)))
        return grade_fail("cannot write %s: %s", path, err.text);
    if (g->shard_n > 0)
        fprintf(g->progress, "grade: wrote %s, shard %d of %d (grade merge makes the report)\n",
                path, g->shard_k, g->shard_n);
    return true;
}

/* Reads the heading's "points" line into g: the part's points and the policy of late work. */
static void get_points(Reader *r, Grading *g)
{
    LatePolicy *l = &g->late;
    double v[12];
    for (int k = 0; k < 12; k++)
        v[k] = results_get_number(r, k + 1);
    g->part_points = v[0];
    *l = (LatePolicy){.due_set = v[1] != 0, .due = v[2], .zone = (int)v[3], .grace = v[4],
                      .per_day = v[5], .cap_set = v[6] != 0, .cap = v[7],
                      .max_days_set = v[8] != 0, .max_days = (int)v[9], .until_set = v[10] != 0,
                      .until = v[11]};
}

/* Reads the heading's lines that every shard must share into g, and their text into
 * g->heading; false (reported) when they are not as put_heading writes them. */
static bool get_heading(Reader *r, Grading *g, const char *work)
{
    char *heading = "";
    int renders = -1, members = -1;
    for (int line = 0; (members < 0 || line < 8 + renders + members) && results_next_line(r);
         line++) {
        heading = grade_format("%s%s", heading, r->raw);
        if (line == 0 && results_line_is(r, "part", 1))
            g->part = results_get_word(r, 1);
        else if (line == 1 && results_line_is(r, "submissions", 1))
            g->submissions = results_get_word(r, 1);
        else if (line == 2 && results_line_is(r, "tolerances", 3))
            g->threshold = results_get_word(r, 1), g->allow = results_get_word(r, 2),
            g->standard = results_get_text(r, 3);
        else if (line == 3 && results_line_is(r, "limits", 3))
            g->time_limit = results_get_number(r, 1),
            g->build_time_limit = results_get_number(r, 2),
            g->memory_limit = (long long)results_get_number(r, 3);
        else if (line == 4 && results_line_is(r, "points", 12))
            get_points(r, g);
        else if (line == 5 && results_line_is(r, "illustrations", 1))
            g->illustrations = results_get_text(r, 1);
        else if (line == 6 && results_line_is(r, "renders", 1) &&
                 (renders = (int)results_get_number(r, 1)) > 0 && renders < 100000)
            g->renders = grade_alloc((size_t)renders * sizeof *g->renders);
        else if (line > 6 && line <= 6 + renders && r->count >= 9 &&
                 results_line_is(r, "render", r->count - 1)) {
            Render *x = &g->renders[g->render_count++];
            *x = (Render){.image = results_get_word(r, 1),
                          .name = results_get_word(r, 2),
                          .scene = results_get_word(r, 3),
                          .points = results_get_number(r, 5),
                          .hidden = results_get_number(r, 6) != 0,
                          .statistical = results_get_number(r, 7) != 0,
                          .visibility = results_get_word(r, 8)};
            x->argv = grade_alloc((size_t)(r->count - 9 + RENDER_WORDS + 1) * sizeof *x->argv);
            for (int k = 9; k < r->count; k++)
                x->argv[RENDER_WORDS + k - 9] = results_get_word(r, k);
            x->reference_show = grade_format("%s/references/%s.png", work, x->name);
        } else if (line == 7 + renders && results_line_is(r, "class", 1) &&
                   (members = (int)results_get_number(r, 1)) >= 0 && members < 1000000)
            g->members = grade_alloc(((size_t)members + 1) * sizeof *g->members);
        else if (line > 7 + renders && line <= 7 + renders + members &&
                 results_line_is(r, "member", 1))
            g->members[g->member_count++] = results_get_word(r, 1);
        else
            r->bad = true;
        if (r->bad)
            return grade_fail("%s:%d: not a line of what grade --shard writes", r->path, r->line);
    }
    g->heading = heading;
    return members >= 0 || grade_fail("%s: cut short after line %d", r->path, r->line);
}

/* Reads the results file r has opened, in the folder whose real path is `real`, into g, its
 * pictures found in REAL/work, and closes it; false (reported) when it is not whole. */
static bool read_results(Grading *g, Reader *r, const char *real)
{
    g->work = grade_format("%s/work", real);
    int count = -1;
    bool ok = (results_next_line(r) && strcmp(r->raw, RESULTS_MAGIC "\n") == 0) ||
              grade_fail("%s is not a results file of this grade", r->path);
    ok = ok && get_heading(r, g, g->work) && results_next_line(r) &&
         results_line_is(r, "shard", 2);
    g->shard_k = ok ? (int)results_get_number(r, 1) : 0;
    g->shard_n = ok ? (int)results_get_number(r, 2) : 0;
    ok = ok && g->shard_n >= 1 && g->shard_n <= 10000 && g->shard_k >= 1 &&
         g->shard_k <= g->shard_n && results_next_line(r) && results_line_is(r, "started", 2) &&
         snprintf(g->started, sizeof g->started, "%s", results_get_word(r, 1)) >= 0 &&
         ((g->sandbox = results_get_text(r, 2)), results_next_line(r)) &&
         results_line_is(r, "submissions", 1) && (count = (int)results_get_number(r, 1)) >= 0 &&
         count <= g->member_count && !r->bad;
    g->subs = grade_alloc(((size_t)count + 1) * sizeof *g->subs);
    while (ok && g->sub_count < count && results_next_line(r))
        ok = results_get_submission(r, g, &g->subs[g->sub_count++], g->work, g->work);
    ok = ok && results_next_line(r) && strcmp(r->raw, "end\n") == 0;
    if (!ok && !r->bad)
        grade_fail("%s:%d: the file is not whole", r->path, r->line);
    free(r->text);
    fclose(r->file);
    return ok;
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
    if ((r.file = path_open_regular(r.path, &kind)) == NULL && kind != NULL)
        return grade_fail("%s is not a regular file (%s): not the results of grade --shard",
                          r.path, kind);
    if (r.file == NULL)
        return grade_fail("no %s: %s is not a folder of grade --shard, or its grading did not "
                          "finish (its log says why)",
                          r.path, folder);
    g->out = folder;
    return read_results(g, &r, real);
}

/* Reads OUT/results.txt, the results of a whole class that grade or grade merge wrote into
 * the folder `out`, into g (for --only); false (reported) when there are none, or they are
 * not whole, or of a slice. */
bool shard_read_class(Grading *g, const char *out)
{
    char real[PATH_MAX];
    const char *kind = NULL;
    Reader r = {.path = grade_format("%s/results.txt", out)};
    if (realpath(out, real) != NULL && (r.file = path_open_regular(r.path, &kind)) == NULL &&
        kind != NULL)
        return grade_fail("--only: %s is not a regular file (%s): not the results of grade",
                          r.path, kind);
    if (r.file == NULL)
        return grade_fail("--only: no %s: %s holds no grading of a class to regrade students "
                          "into (grade and grade merge leave their results there); grade the "
                          "whole class into it first",
                          r.path, out);
    g->out = out;
    return read_results(g, &r, real) &&
           ((g->shard_n == 1 && g->sub_count == g->member_count) ||
            grade_fail("--only: %s holds a slice of a class, not the whole class", r.path));
}

/* Returns the heading that a results file of g would begin with, from its part to its
 * class's last member: what must be the same in a shard.txt or results.txt to be of the
 * same grading (Grading.heading, read back). */
char *shard_format_heading(const Grading *g)
{
    char *text = NULL;
    size_t size = 0;
    FILE *f = open_memstream(&text, &size);
    if (f == NULL)
        return "";
    put_grading(f, g);
    fclose(f);
    char *heading = grade_format("%s", text);
    free(text);
    return heading;
}
