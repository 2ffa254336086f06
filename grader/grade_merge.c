/* grade_merge.c: grade merge: a class's shards checked against one another, made one report. */
#include "grade_merge.h"

#include <errno.h>
#include <fcntl.h>
#include <getopt.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <unistd.h>

#include "grade_base.h"
#include "grade_junit.h"
#include "grade_out.h"
#include "grade_report.h"
#include "grade_run.h"
#include "grade_shard.h"
#include "grading.h"
#include "toolopt.h"

/* What grade merge was asked. */
typedef struct {
    const char *out, *junit;
    bool quiet, help;
} MergeOptions;

/* grade merge's options, in the order of set_option's cases. */
static const ToolOption options[] = {
    {"out", 0, "DIR", "write report.html and grades.csv into DIR\n(default: grading-PART)", NULL},
    {"junit", 0, "FILE", "also write the verdicts as JUnit XML", NULL},
    {"quiet", 'q', NULL, "no progress lines", NULL},
    {"help", 'h', NULL, "show this help and exit", NULL},
};
enum { OPTION_COUNT = sizeof options / sizeof options[0] };

/* Takes option k's value into the MergeOptions `state`. */
static bool set_option(void *state, int k, const char *value)
{
    MergeOptions *m = state;
    const char **texts[] = {&m->out, &m->junit};
    if (k < 2)
        *texts[k] = value;
    else
        *(k == 2 ? &m->quiet : &m->help) = true;
    return true;
}

/* Returns what the first line that differs between two headings of results files (two
 * shards', or a class's and a regrade's) is about, and that line of the first. */
char *merge_describe_difference(const char *a, const char *b)
{
    static const char *const keys[][2] = {
        {"part", "another part"},
        {"submissions", "another class folder"},
        {"tolerances", "other tolerances or another --standard"},
        {"limits", "other limits"},
        {"points", "another grading.conf"},
        {"illustrations", "other references"},
        {"render", "other references or scenes"},
        {"class", "another class: other submissions"},
        {"member", "another class: other submissions"},
    };
    size_t at = 0, start = 0;
    for (; a[at] == b[at] && a[at] != '\0'; at++)
        if (a[at] == '\n')
            start = at + 1;
    const char *line = a + start;
    /* The line's first word names what differs: a render's image, a member's folder. */
    for (size_t k = 0; k < sizeof keys / sizeof keys[0]; k++) {
        size_t len = strlen(keys[k][0]);
        if (strncmp(line, keys[k][0], len) != 0 || line[len] != ' ')
            continue;
        const char *word = line + len + 1 + (line[len + 1] == '=');
        return grade_format("%s (%s %.*s)", keys[k][1], keys[k][0], (int)strcspn(word, " \n"),
                            word);
    }
    return "another heading";
}

/* Checks that the shards were made alike (part, references, options, class) and are the N
 * slices of one class, each once; false (reported) when not. */
static bool check_shards(Grading *sh, int count, char **folders)
{
    const Grading *first = &sh[0];
    int n = first->shard_n;
    int *seen = grade_alloc((size_t)n * sizeof *seen);
    for (int i = 0; i < count; i++) {
        if (strcmp(sh[i].heading, first->heading) != 0)
            return grade_fail("%s and %s were graded from %s: they are not shards of one grading",
                              folders[0], folders[i],
                              merge_describe_difference(first->heading, sh[i].heading));
        if (sh[i].shard_n != n)
            return grade_fail("%s is shard %d of %d, %s of %d", folders[i], sh[i].shard_k,
                              sh[i].shard_n, folders[0], n);
        if (seen[sh[i].shard_k - 1] != 0)
            return grade_fail("shard %d of %d is given twice: %s and %s", sh[i].shard_k, n,
                              folders[seen[sh[i].shard_k - 1] - 1], folders[i]);
        seen[sh[i].shard_k - 1] = i + 1;
    }
    for (int k = 0; k < n; k++)
        if (seen[k] == 0)
            return grade_fail("shard %d of %d is missing: give every shard's folder (%d of %d "
                              "given)",
                              k + 1, n, count, n);
    return true;
}

/* Makes g the whole class of the shards: their heading, and every submission in the class's
 * order, from the shard whose slice holds it; false (reported) when a shard does not hold
 * exactly its slice. */
static bool gather(Grading *g, Grading *sh, int count, char **folders)
{
    int n = sh[0].shard_n, *next = grade_alloc((size_t)n * sizeof *next);
    Grading **of = grade_alloc((size_t)n * sizeof *of);
    for (int i = 0; i < count; i++)
        of[sh[i].shard_k - 1] = &sh[i];
    *g = sh[0];
    g->subs = grade_alloc(((size_t)g->member_count + 1) * sizeof *g->subs);
    g->sub_count = g->member_count;
    for (int i = 0; i < count; i++)
        if (strcmp(sh[i].started, g->started) < 0)
            memcpy(g->started, sh[i].started, sizeof g->started);
    for (int m = 0; m < g->member_count; m++) {
        Grading *s = of[m % n];
        if (next[m % n] >= s->sub_count || strcmp(s->subs[next[m % n]].name, g->members[m]) != 0)
            return grade_fail("%s does not hold its slice of the class: %s is not in it",
                              folders[s - sh], g->members[m]);
        g->subs[m] = s->subs[next[m % n]++];
    }
    for (int k = 0; k < n; k++)
        if (next[k] != of[k]->sub_count)
            return grade_fail("%s holds more than its slice of the class", folders[of[k] - sh]);
    return true;
}

/* Takes a shared lock on a shard's folder, so that a shard still being graded (which holds
 * its lock) is refused, and no grading of it starts while it is read (a FIFO planted as the
 * lock is opened without waiting for a writer); false (reported). */
static bool lock_shard(const char *folder)
{
    char *path = grade_format("%s/.grade-lock", folder);
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOFOLLOW | O_CLOEXEC);
    if (fd >= 0 && flock(fd, LOCK_SH | LOCK_NB) != 0)
        return grade_fail("%s is still being graded (a grade holds %s): wait for it to end", folder,
                          path);
    return true; /* the descriptor stays open, the lock held, until the merge ends */
}

/* Returns path with its folder `from` made `to`: a picture of a shard's work folder named
 * through its link; NULL and a path elsewhere stay as they are. */
static char *rebase(char *path, const char *from, const char *to)
{
    size_t len = strlen(from);
    return path != NULL && strncmp(path, from, len) == 0 && path[len] == '/'
               ? grade_format("%s%s", to, path + len)
               : path;
}

/* Links OUT/work/NAME to each submission's work folder in its shard, so that the report's
 * command lines (cd work/NAME/run) hold from OUT, and names its pictures through the link,
 * as OUT/results.txt keeps them; false (reported) when it cannot. */
static bool link_work(Grading *g)
{
    for (int k = 0; k < g->sub_count; k++) {
        Submission *s = &g->subs[k];
        char *name = strrchr(s->work, '/') + 1, *link = grade_format("%s/%s", g->work, name);
        if (symlink(s->work, link) != 0)
            return grade_fail("cannot link %s to %s: %s", link, s->work, strerror(errno));
        for (int r = 0; r < g->render_count; r++) {
            s->results[r].image_show = rebase(s->results[r].image_show, s->work, link);
            s->results[r].heat_show = rebase(s->results[r].heat_show, s->work, link);
        }
        s->work = link;
    }
    return true;
}

/* Runs grade merge (argv[0] "merge"): reads and checks every shard before it writes
 * anything, then OUT/grades.csv and OUT/report.html; returns the exit status. */
int merge_main(int argc, char **argv)
{
    MergeOptions m = {0};
    static Grading g;
    if (!toolopt_parse("grade merge", options, sizeof options[0], OPTION_COUNT, argc, argv,
                       set_option, &m))
        return 2;
    if (m.help) {
        printf("Usage: grade merge [options] SHARD...\nChecks that the folders SHARD..., "
               "written by grade --shard K/N, are the N shards\nof one grading (one part, "
               "references, options and class) and writes the\nclass's report.html and "
               "grades.csv, as grade without --shard would.\n\nOptions:\n");
        toolopt_print(stdout, options, sizeof options[0], OPTION_COUNT);
        return 0;
    }
    int count = argc - optind;
    char **folders = argv + optind, real[PATH_MAX], out_real[PATH_MAX];
    if (count < 1) {
        fprintf(stderr, "usage: grade merge [options] SHARD... (grade merge --help for more)\n");
        return 2;
    }
    Grading *sh = grade_alloc((size_t)count * sizeof *sh);
    bool ok = true;
    for (int i = 0; ok && i < count; i++)
        ok = lock_shard(folders[i]) && shard_read(&sh[i], folders[i]);
    if (!ok || !check_shards(sh, count, folders) || !gather(&g, sh, count, folders))
        return 2;
    g.out = m.out != NULL ? m.out : grade_format("grading-%s", g.part);
    g.junit = m.junit;
    g.merging = true;
    /* The merge is the whole class: its results go to OUT/results.txt, for --only. */
    g.shard_k = g.shard_n = 0;
    g.progress = m.quiet ? fopen("/dev/null", "w") : stderr;
    g.progress = g.progress != NULL ? g.progress : stderr;
    for (int i = 0; i < count; i++)
        if (realpath(g.out, out_real) != NULL && realpath(folders[i], real) != NULL &&
            (strcmp(out_real, real) == 0 ||
             strstr(real, grade_format("%s/work/", out_real)) == real)) {
            grade_fail("the output folder %s would replace the work of the shard %s: choose "
                       "another --out",
                       g.out, folders[i]);
            return 2;
        }
    run_init();
    ok = out_prepare(&g) && link_work(&g) && report_write(&g) &&
         (g.junit == NULL || junit_export(&g, g.junit)) && shard_write(&g);
    return ok ? 0 : 2;
}
