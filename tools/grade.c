/* grade.c: grades a class's submissions for one part of the course against its reference images. */
#include "grade.h"

#include <errno.h>
#include <getopt.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "grade_part.h"
#include "grade_report.h"
#include "grade_run.h"
#include "grade_submission.h"
#include "imgdiff.h"
#include "stop.h"

enum { EXIT_REPORTED = 0, EXIT_TROUBLE = 2, EXIT_INTERRUPTED = 130 };

/* Prints the usage, the options and their defaults. */
static void print_help(FILE *f)
{
    fprintf(f,
            "Usage: grade [options] PART SUBMISSIONS\n"
            "       grade --self [options] PART FOLDER\n"
            "Grades every submission in the folder SUBMISSIONS against the reference images\n"
            "of PART and writes a report (report.html) and a table (grades.csv).\n"
            "\n"
            "PART is a part of the course: its folder's name (1.1-spheres-red), the start\n"
            "of it (1.1), or the path of its folder. Its references/renders.txt lists the\n"
            "reference images and the scenes they were rendered from.\n"
            "\n"
            "SUBMISSIONS holds a folder a student, either\n"
            "  - images named as the references (spheres-three.png; .pfm, .exr accepted too),\n"
            "  - or sources with a Makefile: make, run in a copy, must build an executable\n"
            "    raytra beside it, which is run as  raytra SCENE OUTPUT [arguments]  for\n"
            "    every scene, in a scratch folder, under the limits below.\n"
            "\n"
            "Options:\n"
            "  --out DIR               write report.html, grades.csv and the work files\n"
            "                          (work/) into DIR (default: grading-PART)\n"
            "  --time-limit S          seconds a student's program may take for one scene\n"
            "                          (default 60; 0: no limit)\n"
            "  --build-time-limit S    seconds make may take (default 300; 0: no limit)\n"
            "  --memory-limit M        address space a student's make or program may use:\n"
            "                          bytes, or with K, M or G (default 2G; 0: no limit)\n"
            "  --threshold T           imgdiff's: a pixel differs when one of its channels\n"
            "                          differs by more than T (default %s)\n"
            "  --allow F               imgdiff's: an image passes when at most the fraction\n"
            "                          F of its pixels differ (default %s)\n"
            "  --self                  FOLDER is one student's program (or images): grade\n"
            "                          it alone, print each scene's verdict and heat map,\n"
            "                          and exit 1 unless every scene passes\n"
            "  -q, --quiet             no progress lines\n"
            "  -h, --help              show this help and exit\n"
            "\n"
            "Exit status: 0 when the report was written, whatever the verdicts; 2 when\n"
            "grading could not be done; 130 when interrupted. See docs/grading.md.\n",
            IMGDIFF_THRESHOLD_TEXT, IMGDIFF_ALLOW_TEXT);
}

/* Returns zeroed memory; ends the grader when there is none, as it cannot go on. */
void *grade_alloc(size_t size)
{
    void *p = calloc(1, size > 0 ? size : 1);
    if (p == NULL) {
        fprintf(stderr, "grade: out of memory\n");
        exit(EXIT_TROUBLE);
    }
    return p;
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

/* Returns a new copy of text. */
char *grade_copy(const char *text)
{
    return grade_format("%s", text);
}

/* Writes a memory limit in words: "2 GiB", "512 MiB", or "none" for 0. */
void grade_size_text(long long bytes, char *text, size_t size)
{
    if (bytes <= 0)
        snprintf(text, size, "none");
    else if (bytes % (1LL << 30) == 0)
        snprintf(text, size, "%lld GiB", bytes >> 30);
    else
        snprintf(text, size, "%lld MiB", bytes >> 20);
}

/* Sets the verdict of res and its reason, made as printf makes it. */
void grade_verdict(SceneResult *res, Verdict v, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(res->message, sizeof res->message, fmt, ap);
    va_end(ap);
    res->verdict = v;
}

/* Reads a number, 0 or more, into *value; with units, K, M or G may follow it for 2^10,
 * 2^20 or 2^30. False when text is not one. */
static bool parse_amount(const char *text, bool units, double *value)
{
    char *end;
    double v = strtod(text, &end);
    const char *all = "KkMmGg";
    const char *unit = units && end != text && *end != '\0' ? strchr(all, *end) : NULL;
    double scale = unit != NULL ? pow(1024.0, (double)((unit - all) / 2 + 1)) : 1;
    end += unit != NULL;
    if (end == text || *end != '\0' || !isfinite(v) || v < 0)
        return false;
    *value = v * scale;
    return true;
}

/* Reads the command line into g and *part, with getopt_long (options may follow the
 * words); false (reported) when it is not a valid one. */
static bool parse_args(int argc, char **argv, Grading *g, const char **part, bool *help)
{
    static const struct option options[] = {
        {"out", required_argument, NULL, 'o'},
        {"time-limit", required_argument, NULL, 't'},
        {"build-time-limit", required_argument, NULL, 'b'},
        {"memory-limit", required_argument, NULL, 'm'},
        {"threshold", required_argument, NULL, 'T'},
        {"allow", required_argument, NULL, 'a'},
        {"self", no_argument, NULL, 's'},
        {"quiet", no_argument, NULL, 'q'},
        {"help", no_argument, NULL, 'h'},
        {0},
    };
    opterr = 0;
    int c;
    bool ok = true;
    double bytes;
    /* The short option string names only -q and -h: the others are long alone. */
    while (ok && (c = getopt_long(argc, argv, ":qh", options, NULL)) != -1) {
        const char *arg = argv[optind - 1];
        switch (c) {
        case 'o': g->out = optarg; break;
        case 'T': g->threshold = optarg; break;
        case 'a': g->allow = optarg; break;
        case 's': g->self = true; break;
        case 'q': g->quiet = true; break;
        case 'h': *help = true; break;
        case 't':
        case 'b':
            if (!parse_amount(optarg, false, c == 't' ? &g->time_limit : &g->build_time_limit)) {
                fprintf(stderr, "grade: %.*s takes a number of seconds, or 0, got '%s'\n",
                        (int)strcspn(arg, "="), arg, optarg);
                ok = false;
            }
            break;
        case 'm':
            /* 0, or at least 1 MiB: a smaller limit is surely a slip. */
            ok = parse_amount(optarg, true, &bytes) && bytes <= 1e18 &&
                 (bytes == 0 || bytes >= 1024.0 * 1024);
            g->memory_limit = ok ? (long long)bytes : 0;
            if (!ok)
                fprintf(stderr,
                        "grade: --memory-limit takes a size such as 512M or 2G, or 0, "
                        "got '%s'\n",
                        optarg);
            break;
        case ':': fprintf(stderr, "grade: %s needs a value\n", arg); return false;
        default:
            fprintf(stderr, "grade: unknown option '%s' (grade --help lists them)\n", arg);
            return false;
        }
    }
    if (!ok || *help)
        return ok;
    if (argc - optind > 2) {
        fprintf(stderr, "grade: unexpected argument '%s': give a part and a folder\n",
                argv[optind + 2]);
        return false;
    }
    if (argc - optind < 2) {
        fprintf(stderr, "usage: grade [options] PART SUBMISSIONS (grade --help for more)\n");
        return false;
    }
    *part = argv[optind];
    g->submissions = argv[optind + 1];
    return true;
}

/* Tells whether path is a folder. */
bool grade_is_folder(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

/* Tells whether path is a regular file. */
bool grade_is_file(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

/* Makes folder path, or with anew false takes the one there; false (reported) when it
 * cannot. Anew, a folder already there (a link a student's program left) is refused. */
bool grade_make_folder(const char *path, bool anew)
{
    if (mkdir(path, 0777) == 0 || (!anew && errno == EEXIST && grade_is_folder(path)))
        return true;
    fprintf(stderr, "grade: cannot make the folder %s: %s\n", path, strerror(errno));
    return false;
}

/* Runs a command of the grader's own (no limits but time); true when it succeeds. */
static bool run_quietly(char **argv, const char *log)
{
    RunSpec spec = {.log = log, .time_limit = 600};
    RunResult r = run_program(argv, &spec);
    return r.end == RUN_EXITED && r.status == 0;
}

/* Makes OUT and an empty OUT/work (an absolute path), removing a work folder of an earlier run (one
 * holding the mark this writes) and refusing to remove any other; false (reported) on trouble. */
static bool prepare_work(Grading *g)
{
    char real[PATH_MAX];
    if (!grade_make_folder(g->out, false))
        return false;
    /* Absolute: students' programs run in folders of their own. */
    if (realpath(g->out, real) == NULL) {
        fprintf(stderr, "grade: cannot find %s: %s\n", g->out, strerror(errno));
        return false;
    }
    g->work = grade_format("%s/work", real);
    char *mark = grade_format("%s/.made-by-grade", g->work);
    bool ok = true;
    if (grade_is_folder(g->work) && !grade_is_file(mark)) {
        fprintf(stderr, "grade: %s exists and was not made by grade: choose another --out\n",
                g->work);
        ok = false;
    } else if (grade_is_folder(g->work)) {
        /* A student's build may have left folders without write permission. */
        char *chmod[] = {"chmod", "-R", "u+rwX", "--", g->work, NULL};
        char *rm[] = {"rm", "-rf", "--", g->work, NULL};
        run_quietly(chmod, NULL);
        if (!run_quietly(rm, NULL)) {
            fprintf(stderr, "grade: cannot remove the old work folder %s\n", g->work);
            ok = false;
        }
    }
    FILE *f = NULL;
    if (ok && (!grade_make_folder(g->work, false) || (f = fopen(mark, "w")) == NULL))
        ok = false;
    if (f != NULL) {
        fprintf(f, "grade's work folder: each run of grade with this --out removes it and "
                   "makes it anew.\n");
        ok = fclose(f) == 0;
    }
    char *refs = grade_format("%s/references", g->work);
    ok = ok && grade_make_folder(refs, false);
    free(refs);
    free(mark);
    return ok;
}

/* Prints the first line of the file at path to stderr after prefix, if there is one. */
void grade_print_first_line(const char *prefix, const char *path)
{
    char line[512] = "";
    FILE *f = fopen(path, "r");
    if (f != NULL) {
        if (fgets(line, sizeof line, f) == NULL)
            line[0] = '\0';
        fclose(f);
    }
    if (line[0] != '\0')
        fprintf(stderr, "%s%s%s", prefix, line, strchr(line, '\n') != NULL ? "" : "\n");
}

/* Asks imgdiff whether it takes the tolerances, before any work; false (reported) when it
 * does not, or when imgdiff cannot run. */
static bool check_imgdiff(const Grading *g)
{
    char *log = grade_format("%s/imgdiff-check.txt", g->work);
    char *argv[] = {g->imgdiff, "--threshold", (char *)g->threshold, "--allow", (char *)g->allow,
                    "--help",   NULL};
    bool ok = run_quietly(argv, log);
    if (!ok) {
        grade_print_first_line("grade: ", log);
        fprintf(stderr, "grade: imgdiff (%s) refused the tolerances or could not run\n",
                g->imgdiff);
    }
    free(log);
    return ok;
}

/* Does all the grading but reading the command line, for part `part`; returns the exit
 * status. */
static int grade(Grading *g, const char *part, const char *argv0)
{
    char *tools_build = NULL;
    char *top = part_find_top(argv0, &tools_build);
    char *part_dir = top != NULL ? part_find(top, part) : NULL;
    int status = EXIT_TROUBLE;
    if (part_dir == NULL)
        goto done;
    g->part = strrchr(part_dir, '/') + 1;
    g->references = grade_format("%s/references", part_dir);
    g->imgdiff = grade_format("%s/imgdiff", tools_build);
    if (g->out == NULL)
        g->out = grade_format("grading-%s", g->part);
    time_t now = time(NULL);
    strftime(g->started, sizeof g->started, "%Y-%m-%d %H:%M", localtime(&now));
    if (access(g->imgdiff, X_OK) != 0) {
        fprintf(stderr, "grade: no imgdiff at %s (make -C tools builds it)\n", g->imgdiff);
        goto done;
    }
    if (!grade_is_folder(g->submissions)) {
        fprintf(stderr, "grade: no folder %s\n", g->submissions);
        goto done;
    }
    if (!part_read_renders(g, top) || !prepare_work(g) || !check_imgdiff(g) ||
        !part_show_references(g) || !submission_list(g))
        goto done;
    if (!g->quiet)
        fprintf(stderr, "grade: part %s, %d scene%s, %d submission%s\n", g->part, g->render_count,
                g->render_count == 1 ? "" : "s", g->sub_count, g->sub_count == 1 ? "" : "s");
    if (!g->quiet && g->illustrations != NULL)
        fprintf(stderr, "grade: not graded (illustrations): %s\n", g->illustrations);
    if (submission_grade_all(g) && report_write(g))
        status = g->self ? report_print_self(g) : EXIT_REPORTED;
done:
    if (stop_requested()) {
        fprintf(stderr, "grade: interrupted: no report written\n");
        status = EXIT_INTERRUPTED;
    }
    free(part_dir);
    free(top);
    free(tools_build);
    return status;
}

/* Runs the grader: exit status 0 when the report was written, 2 when it could not be,
 * 130 when interrupted. */
int main(int argc, char **argv)
{
    /* Static: what grading gathers lives until the exit, which frees it. */
    static Grading g = {.threshold = IMGDIFF_THRESHOLD_TEXT,
                        .allow = IMGDIFF_ALLOW_TEXT,
                        .time_limit = 60,
                        .build_time_limit = 300,
                        .memory_limit = 2LL << 30};
    const char *part = NULL;
    bool help = false;
    if (!parse_args(argc, argv, &g, &part, &help))
        return EXIT_TROUBLE;
    if (help) {
        print_help(stdout);
        return EXIT_REPORTED;
    }
    run_init();
    return grade(&g, part, argv[0]);
}
