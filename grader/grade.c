/* grade.c: grades a class's submissions for one part of the course against its reference images. */
#include "grade.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <time.h>
#include <unistd.h>

#include "imgdiff.h"
#include "progress.h"
#include "stop.h"
#include "toolopt.h"

enum { EXIT_REPORTED = 0, EXIT_TROUBLE = 2, EXIT_INTERRUPTED = 130 };

/* What an option's value is, and so how it is read. */
typedef enum { OPT_FLAG, OPT_TEXT, OPT_COUNT, OPT_SECONDS, OPT_BYTES } OptKind;

/* One option: the common description (toolopt.h), how its value is read, the field of
 * Grading it sets. */
typedef struct {
    ToolOption o;
    OptKind kind;
    size_t field;
} GradeOption;

/* grade's options, from which the parsing, the defaults and --help are all made. */
static const GradeOption options[] = {
    {{"out", 0, "DIR", "write report.html, grades.csv and the work files\n"
      "(work/) into DIR (default: grading-PART)", NULL}, OPT_TEXT, offsetof(Grading, out)},
    {{"time-limit", 0, "S", "seconds a student's program may take for one scene;\n"
      "0: no limit", "60"}, OPT_SECONDS, offsetof(Grading, time_limit)},
    {{"build-time-limit", 0, "S", "seconds make may take; 0: no limit", "300"}, OPT_SECONDS,
     offsetof(Grading, build_time_limit)},
    {{"memory-limit", 0, "M", "address space a student's make or program may use:\n"
      "bytes, or with K, M or G; 0: no limit", "2G"}, OPT_BYTES, offsetof(Grading, memory_limit)},
    {{"disk-limit", 0, "M", "bytes a submission's build or run may leave in its\n"
      "folders: with K, M or G; 0: no limit (the disk's\nlast 256 MiB are never theirs)", "1G"},
     OPT_BYTES, offsetof(Grading, disk_limit)},
    {{"sandbox", 0, "MODE", "where students' builds and programs run: namespaces\n"
      "(bubblewrap: each sees its folder, the toolchain and\nits scene, nothing else), "
      "fallback (a session,\nlimits, with --run-as users of their own), or auto:\n"
      "namespaces when bubblewrap works (docs/grading.md)", "auto"}, OPT_TEXT,
     offsetof(Grading, sandbox)},
    {{"threshold", 0, "T", "imgdiff's: a pixel differs when one of its channels\n"
      "differs by more than T", IMGDIFF_THRESHOLD_TEXT}, OPT_TEXT, offsetof(Grading, threshold)},
    {{"allow", 0, "F", "imgdiff's: an image passes when at most the fraction\n"
      "F of its pixels differ", IMGDIFF_ALLOW_TEXT}, OPT_TEXT, offsetof(Grading, allow)},
    {{"standard", 0, "NAME", "a Monte Carlo render's soft shadows that pass (part\n"
      "1.6): good, stratified or correlated light samples;\nok, random points on the light "
      "too", "good"}, OPT_TEXT, offsetof(Grading, standard)},
    {{"jobs", 'j', "N", "grade N submissions at a time, each under the\n"
      "limits above (see docs/grading.md)", "1"}, OPT_COUNT, offsetof(Grading, jobs)},
    {{"shard", 0, "K/N", "grade only the K-th of N slices of the class and\n"
      "write its results for grade merge (default --out:\ngrading-PART-shard-K-of-N)", NULL},
     OPT_TEXT, offsetof(Grading, shard)},
    {{"run-as", 0, "USERS", "as root: run students' builds and programs as\n"
      "USERS (names or uids, one a job, comma-separated),\n"
      "users of their own whose every process is ended", NULL}, OPT_TEXT,
     offsetof(Grading, run_as)},
    {{"grader-user", 0, "USER", "with --run-as: the user the grader becomes", NULL}, OPT_TEXT,
     offsetof(Grading, grader_user)},
    {{"junit", 0, "FILE", "also write the verdicts as JUnit XML: a test case\n"
      "a submission and scene", NULL}, OPT_TEXT, offsetof(Grading, junit)},
    {{"gradescope", 0, "FILE", "with --self: also write Gradescope's results.json",
      NULL}, OPT_TEXT, offsetof(Grading, gradescope)},
    {{"hidden", 0, "DIR", "also grade the instructor's own scenes of DIR\n(its renders.txt; "
      "default: grading.conf's 'hidden')", NULL}, OPT_TEXT, offsetof(Grading, hidden)},
    {{"grading-conf", 0, "FILE", "the points and visibility of the scenes (default:\n"
      "the part's references/grading.conf)", NULL}, OPT_TEXT, offsetof(Grading, conf)},
    {{"self", 0, NULL, "FOLDER is one student's program (or images): grade\nit alone, "
      "print each scene's verdict and heat map,\nand exit 1 unless every scene passes", NULL},
     OPT_FLAG, offsetof(Grading, self)},
    {{"quiet", 'q', NULL, "no progress lines", NULL}, OPT_FLAG, offsetof(Grading, quiet)},
    {{"help", 'h', NULL, "show this help and exit", NULL}, OPT_FLAG, offsetof(Grading, help)},
};
enum { OPTION_COUNT = sizeof options / sizeof options[0] };
_Static_assert(OPTION_COUNT <= TOOLOPT_MAX, "toolopt parses at most TOOLOPT_MAX options");

/* Prints the usage and the options. */
static void print_help(void)
{
    printf("Usage: grade [options] PART SUBMISSIONS\n"
           "       grade --self [options] PART FOLDER\n"
           "       grade merge [--out DIR] [--junit FILE] [-q] SHARD...\n"
           "Grades every submission in the folder SUBMISSIONS against the reference images\n"
           "of PART (1.1-spheres-red, 1.1, or a part's folder) and writes a report\n"
           "(report.html) and a table (grades.csv). SUBMISSIONS holds a folder a student:\n"
           "images named as the references (spheres-three.png; .pfm, .exr too), or sources\n"
           "with a Makefile whose make, run in a copy, builds raytra beside it, run as\n"
           "  raytra SCENE OUTPUT [arguments]\n"
           "for every scene, in a scratch folder, under the limits below. grade merge\n"
           "writes one report of the folders of the shards of a class (--shard).\n\nOptions:\n");
    toolopt_print(stdout, options, sizeof options[0], OPTION_COUNT);
    printf("\nExit status: 0 when the report was written, whatever the verdicts; 2 when\n"
           "grading could not be done; 130 when interrupted. See docs/grading.md.\n");
}

/* Prints "grade: " and a message made as printf makes it; returns false, to end a chain. */
bool grade_fail(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fputs("grade: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    return false;
}

/* Sets the field of the Grading `state` that option k sets from its value: seconds are a
 * number from 0; a memory limit is bytes, or a number followed by K, M or G (2^10, 2^20,
 * 2^30), 0 or at least 1 MiB (less is surely a slip). False (reported) for a bad value. */
static bool set_option(void *state, int k, const char *value)
{
    static const char units[] = "KkMmGg";
    const GradeOption *o = &options[k];
    void *field = (char *)state + o->field;
    char *end = (char *)value; /* flags have no value */
    double v = o->kind >= OPT_COUNT ? strtod(value, &end) : 0;
    const char *unit = o->kind == OPT_BYTES && end != value && *end != '\0' ? strchr(units, *end)
                                                                             : NULL;
    if (unit != NULL) {
        v = ldexp(v, 10 * (int)((unit - units) / 2 + 1));
        end++;
    }
    if (o->kind == OPT_FLAG)
        *(bool *)field = true;
    else if (o->kind == OPT_TEXT && o->field == offsetof(Grading, standard) &&
             strcmp(value, "good") != 0 && strcmp(value, "ok") != 0)
        return grade_fail("--standard takes good or ok, got '%s'", value);
    else if (o->kind == OPT_TEXT)
        *(const char **)field = value;
    else if (o->kind == OPT_COUNT && (end == value || *end != '\0' || !(v >= 1 && v <= 64) ||
                                      v != floor(v)))
        return grade_fail("--%s takes a whole number from 1 to 64, got '%s'", o->o.name, value);
    else if (o->kind == OPT_COUNT)
        *(int *)field = (int)v;
    else if (end == value || *end != '\0' || !isfinite(v) || v < 0 ||
             (o->kind == OPT_BYTES && (v > 1e18 || (v > 0 && v < 1 << 20))))
        return grade_fail("--%s takes %s, got '%s'", o->o.name,
                          o->kind == OPT_SECONDS ? "a number of seconds, or 0"
                                                 : "a size such as 512M or 2G, or 0",
                          value);
    else if (o->kind == OPT_SECONDS)
        *(double *)field = v;
    else
        *(long long *)field = (long long)v;
    return true;
}

/* Returns zeroed memory that lasts until the exit (what the grader gathers serves the
 * report), each block chained to the one before so that all stay reachable; exits on none. */
void *grade_alloc(size_t size)
{
    static void *last;
    void **block = calloc(1, sizeof(max_align_t) + size);
    if (block == NULL) {
        grade_fail("out of memory");
        exit(EXIT_TROUBLE);
    }
    *block = last;
    last = block;
    return (char *)block + sizeof(max_align_t);
}

/* Returns a new string made as printf makes it. */
char *grade_format(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int len = vsnprintf(NULL, 0, fmt, ap);
    va_end(ap);
    char *s = grade_alloc((size_t)len + 1);
    va_start(ap, fmt);
    vsnprintf(s, (size_t)len + 1, fmt, ap);
    va_end(ap);
    return s;
}

/* Returns a memory limit in words: "2 GiB", "512 MiB", or "none" for 0. */
char *grade_size_text(long long bytes)
{
    return bytes <= 0                  ? "none"
           : bytes % (1LL << 30) == 0 ? grade_format("%lld GiB", bytes >> 30)
                                      : grade_format("%lld MiB", bytes >> 20);
}

/* Returns the kind of the file at path, links followed: S_IFDIR, S_IFREG...; 0 for none. */
int grade_kind(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 ? (int)(st.st_mode & S_IFMT) : 0;
}

/* Makes the folder path, refusing anything already there (a link a student left). */
bool grade_make_folder(const char *path)
{
    return mkdir(path, 0777) == 0 ||
           grade_fail("cannot make the folder %s: %s", path, strerror(errno));
}

/* Makes the folder path anew for the grader's work. Anything already there (a folder or a
 * link that a student's program made) is moved aside, renamed, never followed, to a hidden
 * .moved-N-NAME beside it, told on `notes`. Returns NULL, or why the folder was not made. */
const char *grade_fresh_folder(const char *path, FILE *notes)
{
    struct stat st;
    const char *slash = strrchr(path, '/');
    for (int n = 1; lstat(path, &st) == 0; n++) {
        char *aside = grade_format("%.*s/.moved-%d-%s", (int)(slash - path), path, n, slash + 1);
        if (n > 100)
            return grade_format("%s is there already and cannot be moved aside", path);
        if (lstat(aside, &st) == 0 || errno != ENOENT)
            continue;
        if (rename(path, aside) != 0)
            return grade_format("cannot move %s aside: %s", path, strerror(errno));
        fprintf(notes,
                "grade: note: %s was there before grade made it (a program of the class made "
                "it?): moved aside to %s\n",
                path, aside);
    }
    return mkdir(path, 0777) == 0 ? NULL
                                  : grade_format("cannot make %s: %s", path, strerror(errno));
}

/* Returns the names of the folders in `folder`, hidden ones left out, in strcmp's order;
 * sets *count. NULL (and errno) when the folder cannot be read. */
char **grade_list_folders(const char *folder, int *count)
{
    struct dirent **entries;
    int n = scandir(folder, &entries, NULL, alphasort);
    char **names = n >= 0 ? grade_alloc(((size_t)n + 1) * sizeof *names) : NULL;
    *count = 0;
    for (int k = 0; k < n; k++) {
        const char *name = entries[k]->d_name;
        if (name[0] != '.' && grade_kind(grade_format("%s/%s", folder, name)) == S_IFDIR)
            names[(*count)++] = grade_format("%s", name);
        free(entries[k]);
    }
    if (n >= 0)
        free(entries);
    return names;
}

/* Returns why the output folder, at `out` (its real path), cannot serve: it is the
 * submissions folder, or inside a submission (which is copied to be built, and would copy
 * itself), or the submissions are inside its work folder (which is made anew); NULL when it
 * can. A folder of a class that is the output folder is not graded (submission_list). */
static char *out_refusal(const Grading *g, const char *out)
{
    char subs[PATH_MAX];
    if (realpath(g->submissions, subs) == NULL)
        return grade_format("cannot find the folder %s: %s", g->submissions, strerror(errno));
    size_t len = strlen(subs), out_len = strlen(out);
    const char *rest = strncmp(out, subs, len) == 0 && (out[len] == '/' || len == 1)
                           ? out + len + (len > 1)
                           : NULL;
    char *work = grade_format("%s/work", out);
    if (strcmp(out, subs) == 0)
        return grade_format("the output folder %s is the submissions folder: its work folder would "
                            "be graded as a student's; choose an --out outside it",
                            g->out);
    if (rest != NULL && g->shard_n > 0)
        return grade_format("the output folder %s of a shard is inside the class %s: the "
                            "other shards would list it as a submission; choose an --out "
                            "outside it",
                            g->out, g->submissions);
    if (rest != NULL && (g->self || strchr(rest, '/') != NULL))
        return grade_format(
            "the output folder %s is inside the submission %s, which grade copies "
            "to build it; choose an --out outside it",
            g->out, g->self ? g->submissions : grade_format("%.*s", (int)strcspn(rest, "/"), rest));
    if (strncmp(subs, work, out_len + 5) == 0 &&
        (subs[out_len + 5] == '/' || subs[out_len + 5] == 0))
        return grade_format("the submissions folder %s is within %s, which grade makes anew; "
                            "choose another --out",
                            g->submissions, work);
    return NULL;
}

/* Locks the output folder for this run: an exclusive flock on OUT/.grade-lock, held until
 * the grader exits (its descriptor stays open, closed in every child), so that a second run
 * on the same --out refuses rather than mixing its work with this one's; false (reported). */
static bool lock_out(const Grading *g, const char *out)
{
    char *path = grade_format("%s/.grade-lock", out);
    int fd = open(path, O_RDWR | O_CREAT | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC, 0666);
    if (fd < 0)
        return grade_fail("cannot open the lock file %s: %s", path, strerror(errno));
    if (flock(fd, LOCK_EX | LOCK_NB) == 0)
        return true;
    int err = errno;
    close(fd);
    return err == EWOULDBLOCK
               ? grade_fail("%s is in use: another grade is writing into it (it holds %s); wait "
                            "for it to end, or choose another --out",
                            g->out, path)
               : grade_fail("cannot lock %s: %s", path, strerror(err));
}

/* Makes OUT (grading-PART by default), when it may serve, and locks it; makes OUT/work anew,
 * an absolute path as students' programs run elsewhere, removing only a work folder that an
 * earlier run marked. */
bool grade_prepare_out(Grading *g)
{
    char real[PATH_MAX];
    struct stat st;
    g->out = g->out != NULL ? g->out : grade_format("grading-%s", g->part);
    bool made = grade_kind(g->out) != S_IFDIR;
    if ((made && !grade_make_folder(g->out)) || realpath(g->out, real) == NULL)
        return false;
    char *refusal = g->merging ? NULL : out_refusal(g, real);
    if (refusal != NULL) {
        if (made)
            rmdir(g->out);
        return grade_fail("%s", refusal);
    }
    g->work = grade_format("%s/work", real);
    if (!lock_out(g, real))
        return false;
    /* A shard's results go before its work does: they would name pictures no longer there. */
    if (g->shard_n > 0 && unlink(grade_format("%s/shard.txt", real)) != 0 && errno != ENOENT)
        return grade_fail("cannot remove the shard's old results in %s: %s", g->out,
                          strerror(errno));
    /* lstat: a link at the work folder's path is not a work folder grade made. */
    if (lstat(g->work, &st) == 0 &&
        (!S_ISDIR(st.st_mode) || grade_kind(grade_format("%s/.made-by-grade", g->work)) == 0))
        return grade_fail("%s exists and was not made by grade: choose another --out", g->work);
    /* chmod first: a student's build may have left folders read-only; with --run-as, its
     * users make their files in the work folder the grader's to remove. */
    if (lstat(g->work, &st) == 0)
        contain_release(g->work);
    char *anew[] = {"sh", "-c",
                    "chmod -R u+rwX -- \"$1\"; rm -rf -- \"$1\" && mkdir -- \"$1\" "
                    "\"$1/references\" \"$1/canaries\" && chmod 700 -- \"$1/references\" && echo \"grade's work folder: each run of grade with this "
                    "--out removes it and makes it anew.\" >\"$1/.made-by-grade\"",
                    "sh", g->work, NULL};
    if (!run_program(anew, NULL, NULL, 600, 0).ok)
        return grade_fail("cannot make the work folder %s anew", g->work);
    /* With --run-as, the students' users cross both to their folders, whatever the umask. */
    return !contain_active() ||
           ((stat(real, &st) == 0 && chmod(real, (st.st_mode & 07777) | 0111) == 0 &&
             chmod(g->work, 0711) == 0) ||
            grade_fail("cannot let the students' users cross %s: %s", real, strerror(errno)));
}

/* Has imgdiff compare each reference with itself before any work, which checks both the
 * image and the tolerances and makes the report's thumbnail; false (reported) on trouble. */
static bool show_references(Grading *g)
{
    for (int k = 0; k < g->render_count; k++) {
        Render *r = &g->renders[k];
        char *log = grade_format("%s/references/%s.log", g->work, r->name);
        r->reference_show = grade_format("%s/references/%s.png", g->work, r->name);
        /* A Monte Carlo render's statistics judge raytra's own render, which ships beside. */
        char *image =
            r->statistical ? grade_format("%s/%s", g->references, r->image) : r->reference;
        char *argv[] = {g->imgdiff, "-q", "--threshold", (char *)g->threshold, "--allow",
                        (char *)g->allow, "--standard", (char *)g->standard, "--thumb",
                        r->reference_show, "--", r->reference, image, NULL};
        RunResult run = run_program(argv, NULL, log, 600, 0);
        if (!run.ok) {
            char *said = run_tail(run.output);
            return !stop_requested() && grade_fail("%s", said ? said : "imgdiff could not run");
        }
    }
    return true;
}

/* Finds the top of the repository, g->top, two folders above the grader's program
 * (grader/build/grade), and imgdiff in compare/'s folder of the same build; false (reported)
 * when it is not there. */
static bool find_top(Grading *g)
{
    char exe[PATH_MAX] = "", real[PATH_MAX];
    if (realpath("/proc/self/exe", exe) != NULL)
        *strrchr(exe, '/') = '\0';
    if (realpath(grade_format("%s/../../milestones", exe), real) == NULL ||
        grade_kind(real) != S_IFDIR)
        return grade_fail("cannot find the raytra repository: the grader must stay in "
                          "grader/build/ of its checkout");
    g->top = grade_format("%.*s", (int)(strrchr(real, '/') - real), real);
    g->imgdiff = grade_format("%s/compare/%s/imgdiff", g->top, strrchr(exe, '/') + 1);
    return access(g->imgdiff, X_OK) == 0 ||
           grade_fail("no imgdiff at %s (make -C compare builds it)", g->imgdiff);
}

/* Runs the grader: exit status 0 when the report was written (with --self, 1 when a scene
 * did not pass), 2 when it could not be, 130 when interrupted. */
int main(int argc, char **argv)
{
    static Grading g;
    if (argc > 1 && strcmp(argv[1], "merge") == 0)
        return merge_main(argc - 1, argv + 1);
    for (int k = 0; k < OPTION_COUNT; k++)
        if (options[k].o.fallback != NULL)
            set_option(&g, k, options[k].o.fallback);
    if (!toolopt_parse("grade", options, sizeof options[0], OPTION_COUNT, argc, argv,
                       set_option, &g))
        return EXIT_TROUBLE;
    if (g.help) {
        print_help();
        return EXIT_REPORTED;
    }
    if (argc - optind != 2) {
        fprintf(stderr, "usage: grade [options] PART SUBMISSIONS (grade --help for more)\n");
        return EXIT_TROUBLE;
    }
    g.submissions = argv[optind + 1];
    FILE *none = g.quiet ? fopen("/dev/null", "w") : NULL;
    g.progress = none != NULL ? none : stderr;
    g.began = clock_now();
    time_t now = time(NULL);
    strftime(g.started, sizeof g.started, "%Y-%m-%d %H:%M", localtime(&now));
    run_init();
    bool ok = contain_start(g.run_as, g.grader_user, g.jobs) && sandbox_choose(&g) &&
              find_top(&g) && part_find(&g, argv[optind]) && shard_parse(&g) &&
              (grade_kind(g.submissions) == S_IFDIR ||
               grade_fail("no folder %s", g.submissions)) &&
              part_read_renders(&g) && part_read_conf(&g) && grade_prepare_out(&g) &&
              part_render_hidden(&g) && show_references(&g) &&
              (part_make_canaries(&g), submission_list(&g)) && (shard_select(&g), jobs_grade_all(&g)) &&
              (g.shard_n > 0 ? shard_write(&g) : report_write(&g)) &&
              (g.junit == NULL || export_junit(&g, g.junit)) &&
              (g.gradescope == NULL || export_gradescope(&g, g.gradescope));
    if (stop_requested()) {
        grade_fail(g.shard_n > 0 ? "interrupted: the shard's results (shard.txt) were not "
                                   "written: grade the shard again"
                                 : "interrupted: no report written");
        return EXIT_INTERRUPTED;
    }
    if (!ok)
        return EXIT_TROUBLE;
    return g.self ? report_print_self(&g) : EXIT_REPORTED;
}
