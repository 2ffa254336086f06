/* grade_regrade.c: --only: some students graded again into a class's earlier grading, the others' results kept. */
#include "grade_regrade.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "grade_base.h"
#include "grade_merge.h"
#include "grade_out.h"
#include "grade_path.h"
#include "grade_results.h"
#include "grade_run.h"
#include "grade_shard.h"
#include "outfile.h"

/* Checks that --only goes with the options given: not with --self nor --shard (a regrade
 * is of a whole class), nor --gradescope (one submission's); false (reported) when not. */
bool regrade_parse(const Grading *g)
{
    if (g->only == NULL)
        return true;
    if (g->self || g->shard != NULL || g->gradescope != NULL)
        return grade_fail("--only cannot go with %s: it regrades students of a whole class "
                          "graded into --out",
                          g->self            ? "--self"
                          : g->shard != NULL ? "--shard"
                                             : "--gradescope");
    return g->only[0] != '\0' || grade_fail("--only takes the names of submissions, got ''");
}

/* Reads into `earlier` the grading of the class that OUT holds (OUT/results.txt), once OUT
 * is locked and before anything in it changes; false (reported) when there is none, or it
 * is of another part. */
bool regrade_read(const Grading *g, Grading *earlier)
{
    if (g->only == NULL)
        return true;
    if (!shard_read_class(earlier, g->out))
        return false;
    return strcmp(earlier->part, g->part) == 0 ||
           grade_fail("--only: %s holds a grading of part %s, not of %s: give its part, or "
                      "grade the whole class into another --out",
                      g->out, earlier->part, g->part);
}

/* Returns the index of the member named `name` in g's class, or -1. */
static int member_index(const Grading *g, const char *name)
{
    for (int m = 0; m < g->member_count; m++)
        if (strcmp(g->members[m], name) == 0)
            return m;
    return -1;
}

/* Marks in `chosen` (one a member) the names of --only: comma-separated, a name that holds
 * commas taken whole where its parts name no submission; false (reported) for a name that
 * is not a submission of the class. */
static bool choose_named(const Grading *g, bool *chosen)
{
    char **parts = grade_alloc((strlen(g->only) + 1) * sizeof *parts);
    int count = 0;
    for (const char *p = g->only;; p += strcspn(p, ",") + 1) {
        parts[count++] = grade_format("%.*s", (int)strcspn(p, ","), p);
        if (p[strcspn(p, ",")] == '\0')
            break;
    }
    for (int i = 0; i < count;) {
        int m = -1, j = count;
        /* The longest run of parts that names a submission, a folder "smith, ann" too. */
        while (m < 0 && j-- > i) {
            char *name = parts[i];
            for (int k = i + 1; k <= j; k++)
                name = grade_format("%s,%s", name, parts[k]);
            m = member_index(g, name);
        }
        if (m < 0)
            return grade_fail("--only: '%s' is not a submission of %s: give the names of its "
                              "folders (%s%s%s)",
                              parts[i], g->submissions, g->members[0],
                              g->member_count > 1 ? ", " : "",
                              g->member_count > 2   ? grade_format("%s, ...", g->members[1])
                              : g->member_count > 1 ? g->members[1]
                                                    : "");
        chosen[m] = true;
        i = j + 1;
    }
    return true;
}

/* Marks in `chosen` too the students of a regrade of OUT that did not finish (OUT/.regrading
 * names them): their work folders were begun anew, their results are not. */
static void choose_unfinished(const Grading *g, bool *chosen)
{
    const char *kind;
    Reader r = {.path = grade_format("%s/.regrading", g->out)};
    if ((r.file = path_open_regular(r.path, &kind)) == NULL)
        return;
    if (results_next_line(&r) && r.count > 1 && strcmp(r.word[0], "regrading") == 0)
        for (int k = 1; k < r.count && !r.bad; k++) {
            int m = member_index(g, results_get_word(&r, k));
            if (m >= 0 && !chosen[m])
                fprintf(g->progress,
                        "grade: %s's regrade did not finish before: regraded "
                        "too\n",
                        g->members[m]);
            if (m >= 0)
                chosen[m] = true;
        }
    free(r.text);
    fclose(r.file);
}

/* Checks that the class and its grading are those of OUT's earlier one: the same heading
 * (part, references, options, class), the class's folder the same one however named;
 * false (reported) when not. */
static bool check_same(Grading *g, const Grading *earlier)
{
    char a[PATH_MAX], b[PATH_MAX];
    const char *given = g->submissions;
    if (realpath(earlier->submissions, a) != NULL && realpath(given, b) != NULL &&
        strcmp(a, b) == 0)
        g->submissions = earlier->submissions;
    char *heading = shard_format_heading(g);
    g->submissions = given;
    return strcmp(heading, earlier->heading) == 0 ||
           grade_fail("--only: %s was graded from %s: give --only the class and options it "
                      "was graded with, or grade the whole class",
                      g->out, merge_describe_difference(earlier->heading, heading));
}

/* Writes OUT/.regrading, the names of the students being regraded, before their work folders
 * are begun anew: should the regrade not finish, the next one regrades them too. */
static bool mark_regrading(const Grading *g, const bool *chosen)
{
    char *path = grade_format("%s/.regrading", g->out);
    OutFile out;
    Error err;
    bool ok = outfile_open(&out, path, &err);
    if (ok) {
        fputs("regrading", out.file);
        for (int m = 0; m < g->member_count; m++)
            if (chosen[m])
                results_put_text(out.file, g->members[m]);
        fputc('\n', out.file);
    }
    return (ok && outfile_commit(&out, &err)) || grade_fail("cannot write %s: %s", path, err.text);
}

/* Removes the earlier work folder of submission s (a merge's link to its shard's, or the
 * folder an earlier run made), for it to be made anew; false (reported) when it cannot. */
static bool clear_work(const Submission *s)
{
    struct stat st;
    if (lstat(s->work, &st) != 0)
        return true;
    if (!S_ISDIR(st.st_mode))
        return unlink(s->work) == 0 || grade_fail("cannot remove %s", s->work);
    /* As out_prepare does for the whole work folder: the students' users' files opened. */
    chmod(s->work, 0711);
    out_release(s->work);
    char *rm[] = {"sh", "-c", "chmod -R u+rwX -- \"$1\"; rm -rf -- \"$1\"", "sh", s->work, NULL};
    return run_program(rm, NULL, NULL, 600, 0).ok ||
           grade_fail("cannot remove %s, the earlier work of %s", s->work, s->name);
}

/* Keeps in g->subs the submissions --only names (and those of an unfinished regrade), once
 * the class and the grading are checked to be OUT's earlier ones, and clears their earlier
 * work; false (reported) when a name is no submission, or the grading is another. */
bool regrade_select(Grading *g, const Grading *earlier)
{
    if (g->only == NULL)
        return true;
    bool *chosen = grade_alloc((size_t)g->member_count * sizeof *chosen);
    if (!choose_named(g, chosen) || !check_same(g, earlier))
        return false;
    for (int m = 0; m < g->member_count; m++)
        if (strcmp(earlier->subs[m].name, g->members[m]) != 0)
            return grade_fail("--only: %s/results.txt does not hold its class in order (%s)",
                              g->out, g->members[m]);
    choose_unfinished(g, chosen);
    int kept = 0;
    for (int k = 0; k < g->sub_count; k++)
        if (chosen[k])
            g->subs[kept++] = g->subs[k];
    g->sub_count = kept;
    if (!mark_regrading(g, chosen))
        return false;
    for (int k = 0; k < g->sub_count; k++)
        if (!clear_work(&g->subs[k]))
            return false;
    return true;
}

/* Writes a student's name on f with its control characters made '?', as the lines of the
 * submissions show it. */
static void put_name(FILE *f, const char *name)
{
    for (const char *p = name; *p != '\0'; p++)
        fputc((unsigned char)*p < 0x20 || *p == 0x7F ? '?' : *p, f);
}

/* Makes g the whole class again once its chosen students are graded: each member's
 * submission, graded now or kept from `earlier`, in the class's order; tells which. */
bool regrade_gather(Grading *g, const Grading *earlier)
{
    if (g->only == NULL)
        return true;
    Submission *all = grade_alloc(((size_t)g->member_count + 1) * sizeof *all);
    int graded = 0;
    fputs("grade: regraded ", g->progress);
    for (int m = 0; m < g->member_count; m++) {
        bool now = graded < g->sub_count && strcmp(g->subs[graded].name, g->members[m]) == 0;
        all[m] = now ? g->subs[graded++] : earlier->subs[m];
        if (now && graded > 1)
            fputs(", ", g->progress);
        if (now)
            put_name(g->progress, all[m].name);
    }
    if (graded < g->member_count)
        fprintf(g->progress,
                "; the results of the other %d of the class's %d submissions are "
                "kept from %s/results.txt\n",
                g->member_count - graded, g->member_count, g->out);
    else
        fputs(": the whole class\n", g->progress);
    g->subs = all;
    g->sub_count = g->member_count;
    return true;
}

/* Removes OUT/.regrading once the class's results are written: the regrade finished. */
bool regrade_finish(const Grading *g)
{
    return g->only == NULL || unlink(grade_format("%s/.regrading", g->out)) == 0 ||
           grade_fail("cannot remove %s/.regrading", g->out);
}
