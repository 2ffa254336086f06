/* grade.c: grades a class's submissions for one part of the course against its reference images. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "containment.h"
#include "grade_base.h"
#include "grade_conf.h"
#include "grade_gradescope.h"
#include "grade_handin.h"
#include "grade_jobs.h"
#include "grade_junit.h"
#include "grade_late.h"
#include "grade_merge.h"
#include "grade_metadata.h"
#include "grade_out.h"
#include "grade_part.h"
#include "grade_path.h"
#include "grade_regrade.h"
#include "grade_renders.h"
#include "grade_report.h"
#include "grade_run.h"
#include "grade_self.h"
#include "grade_shard.h"
#include "grade_submission.h"
#include "grading.h"
#include "imgdiff.h"
#include "progress.h"
#include "sandbox.h"
#include "stop.h"
#include "toolopt.h"

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
    {{"out", 0, "DIR", "write report.html, grades.csv, gradebook.csv and the\n"
      "work files (work/) into DIR (default: grading-PART)", NULL}, OPT_TEXT,
     offsetof(Grading, out)},
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
    {{"only", 0, "NAMES", "regrade only the submissions NAMES (comma-\n"
      "separated) into the class graded in --out before:\nthe others' results are kept, "
      "the report rewritten", NULL}, OPT_TEXT, offsetof(Grading, only)},
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
    {{"due", 0, "TIME", "the due date, in place of grading.conf's: ISO 8601\n"
      "with its time zone (2026-03-01T23:59:00-05:00)", NULL}, OPT_TEXT,
     offsetof(Grading, due_given)},
    {{"late-until", 0, "TIME", "late work is taken until TIME, in place of\n"
      "grading.conf's late_until; later work gets 0", NULL}, OPT_TEXT,
     offsetof(Grading, until_given)},
    {{"submitted-at", 0, "TIME", "with --self: when the submission was handed in\n"
      "(Gradescope's time), in place of its files' time", NULL}, OPT_TEXT,
     offsetof(Grading, submitted_at)},
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
           "       grade --only NAME[,NAME...] --out OUT [options] PART SUBMISSIONS\n"
           "       grade merge [--out DIR] [--junit FILE] [-q] SHARD...\n"
           "       grade metadata FILE   (Gradescope's submission_metadata.json: its times)\n"
           "Grades every submission in the folder SUBMISSIONS against the reference images\n"
           "of PART (1.1-spheres-red, 1.1, or a part's folder) and writes a report\n"
           "(report.html) and tables (grades.csv, a line a scene; gradebook.csv, a line a\n"
           "student). SUBMISSIONS holds a folder a student: images named as the references\n"
           "(spheres-three.png; .pfm, .exr too), or sources with a Makefile whose make, run\n"
           "in a copy, builds raytra beside it, run as\n"
           "  raytra SCENE OUTPUT [arguments]\n"
           "for every scene, in a scratch folder, under the limits below. grade merge\n"
           "writes one report of the folders of the shards of a class (--shard); --only\n"
           "grades some students again into the class's grading in OUT.\n\nOptions:\n");
    toolopt_print(stdout, options, sizeof options[0], OPTION_COUNT);
    printf("\nExit status: 0 when the report was written, whatever the verdicts; 2 when\n"
           "grading could not be done; 130 when interrupted. See docs/grading.md.\n");
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

/* Runs the grader: exit status 0 when the report was written (with --self, 1 when a scene
 * did not pass), 2 when it could not be, 130 when interrupted. */
int main(int argc, char **argv)
{
    static Grading g, earlier; /* earlier: OUT's grading of the class, for --only */
    if (argc > 1 && strcmp(argv[1], "merge") == 0)
        return merge_main(argc - 1, argv + 1);
    if (argc > 1 && strcmp(argv[1], "metadata") == 0)
        return metadata_main(argc - 1, argv + 1);
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
    sandbox_tell_as("grade");
    bool ok = (g.sandbox = containment_start(g.run_as, g.grader_user, g.jobs, g.sandbox)) != NULL &&
              part_find_top(&g) && part_find(&g, argv[optind]) && shard_parse(&g) &&
              regrade_parse(&g) &&
              (path_kind(g.submissions) == S_IFDIR ||
               grade_fail("no folder %s", g.submissions)) &&
              renders_read(&g) && conf_read(&g) && late_read_options(&g) &&
              out_prepare(&g) && regrade_read(&g, &earlier) &&
              part_render_hidden(&g) && part_show_references(&g) &&
              (part_make_canaries(&g), submission_list(&g)) &&
              (shard_select(&g), regrade_select(&g, &earlier)) && jobs_grade_all(&g) &&
              regrade_gather(&g, &earlier) && (handin_find_all(&g), true) &&
              (g.shard_n > 0 ? shard_write(&g) : report_write(&g)) &&
              /* A class's results, for a later --only: OUT/results.txt. */
              (g.shard_n > 0 || g.self || (shard_write(&g) && regrade_finish(&g))) &&
              (g.junit == NULL || junit_export(&g, g.junit)) &&
              (g.gradescope == NULL || gradescope_export(&g, g.gradescope));
    containment_finish();
    if (stop_requested()) {
        grade_fail(g.shard_n > 0 ? "interrupted: the shard's results (shard.txt) were not "
                                   "written: grade the shard again"
                   : g.only != NULL ? "interrupted: the report and results in the output "
                                      "folder are still the earlier grading's; the next "
                                      "--only into it regrades these students again"
                                    : "interrupted: no report written");
        return EXIT_INTERRUPTED;
    }
    if (!ok)
        return EXIT_TROUBLE;
    return g.self ? self_print(&g) : EXIT_REPORTED;
}
