/* grade.c: grades a class's submissions for one part of the course against its reference images. */
#include "grade.h"

#include <dirent.h>
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

#include "cli.h"
#include "grade_report.h"
#include "grade_run.h"
#include "grade_submission.h"
#include "grade_thumb.h"
#include "imgdiff.h"
#include "stop.h"

enum { EXIT_REPORTED = 0, EXIT_TROUBLE = 2, EXIT_INTERRUPTED = 130 };

/* What the command line asks for. */
typedef struct {
    const char *part, *submissions, *out;
    const char *threshold, *allow;
    double time_limit, build_time_limit;
    long long memory_limit;
    bool quiet, help;
    bool self; /* SUBMISSIONS is one student's folder: a check before handing in */
} GradeOptions;

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

/* Reads a number of seconds, 0 or more; false when text is not one. */
static bool parse_seconds(const char *text, double *seconds)
{
    char *end;
    double v = strtod(text, &end);
    if (end == text || *end != '\0' || !isfinite(v) || v < 0)
        return false;
    *seconds = v;
    return true;
}

/* Reads a size in bytes, with K, M or G for 2^10, 2^20, 2^30: 0, or at least 1M (a
 * smaller one is surely a slip); false when text is not one. */
static bool parse_size(const char *text, long long *bytes)
{
    char *end;
    double v = strtod(text, &end);
    const char *units = "KkMmGg", *unit = *end != '\0' ? strchr(units, *end) : NULL;
    double scale = unit != NULL ? pow(1024.0, (double)((unit - units) / 2 + 1)) : 1;
    end += unit != NULL;
    if (end == text || *end != '\0' || !isfinite(v) || v < 0 || v * scale > 1e18 ||
        (v > 0 && v * scale < 1024.0 * 1024))
        return false;
    *bytes = (long long)(v * scale);
    return true;
}

/* Reads the command line into o, with getopt_long (options may follow the words); false
 * (reported) when it is not a valid one. */
static bool parse_args(int argc, char **argv, GradeOptions *o)
{
    enum {
        OPT_OUT = 256,
        OPT_TIME,
        OPT_BUILD_TIME,
        OPT_MEMORY,
        OPT_THRESHOLD,
        OPT_ALLOW,
        OPT_SELF
    };
    static const struct option options[] = {
        {"out", required_argument, NULL, OPT_OUT},
        {"time-limit", required_argument, NULL, OPT_TIME},
        {"build-time-limit", required_argument, NULL, OPT_BUILD_TIME},
        {"memory-limit", required_argument, NULL, OPT_MEMORY},
        {"threshold", required_argument, NULL, OPT_THRESHOLD},
        {"allow", required_argument, NULL, OPT_ALLOW},
        {"self", no_argument, NULL, OPT_SELF},
        {"quiet", no_argument, NULL, 'q'},
        {"help", no_argument, NULL, 'h'},
        {0},
    };
    *o = (GradeOptions){.threshold = IMGDIFF_THRESHOLD_TEXT,
                        .allow = IMGDIFF_ALLOW_TEXT,
                        .time_limit = 60,
                        .build_time_limit = 300,
                        .memory_limit = 2LL << 30};
    opterr = 0;
    int c;
    bool ok = true;
    while (ok && (c = getopt_long(argc, argv, ":qh", options, NULL)) != -1) {
        const char *arg = argv[optind - 1];
        switch (c) {
        case OPT_OUT: o->out = optarg; break;
        case OPT_THRESHOLD: o->threshold = optarg; break;
        case OPT_ALLOW: o->allow = optarg; break;
        case OPT_SELF: o->self = true; break;
        case 'q': o->quiet = true; break;
        case 'h': o->help = true; break;
        case OPT_TIME:
        case OPT_BUILD_TIME:
            if (!parse_seconds(optarg, c == OPT_TIME ? &o->time_limit : &o->build_time_limit)) {
                fprintf(stderr, "grade: %.*s takes a number of seconds, or 0, got '%s'\n",
                        (int)strcspn(arg, "="), arg, optarg);
                ok = false;
            }
            break;
        case OPT_MEMORY:
            if (!parse_size(optarg, &o->memory_limit)) {
                fprintf(stderr,
                        "grade: --memory-limit takes a size such as 512M or 2G, or 0, "
                        "got '%s'\n",
                        optarg);
                ok = false;
            }
            break;
        case ':': fprintf(stderr, "grade: %s needs a value\n", arg); return false;
        default:
            fprintf(stderr, "grade: unknown option '%s' (grade --help lists them)\n", arg);
            return false;
        }
    }
    if (!ok || o->help)
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
    o->part = argv[optind];
    o->submissions = argv[optind + 1];
    return true;
}

/* Tells whether path is a folder. */
static bool is_folder(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode);
}

/* Tells whether path is a regular file. */
static bool is_file(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

/* Returns the top of the repository, two folders above the grader's program
 * (tools/build/grade), or NULL (reported) when it is not there. */
static char *find_top(const char *argv0, char **tools_build)
{
    char exe[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n > 0)
        exe[n] = '\0';
    else if (realpath(argv0, exe) == NULL)
        exe[0] = '\0';
    char *slash = strrchr(exe, '/');
    char *top = NULL;
    if (slash != NULL) {
        *slash = '\0';
        *tools_build = grade_copy(exe);
        char *up = grade_format("%s/../..", exe);
        char real[PATH_MAX];
        if (realpath(up, real) != NULL)
            top = grade_copy(real);
        free(up);
    }
    char *milestones = top != NULL ? grade_format("%s/milestones", top) : NULL;
    if (milestones == NULL || !is_folder(milestones)) {
        fprintf(stderr, "grade: cannot find the raytra repository: the grader must stay in "
                        "tools/build/ of its checkout\n");
        free(top);
        top = NULL;
    }
    free(milestones);
    return top;
}

/* Tells whether a folder's entry is not hidden, for scandir. */
static int visible(const struct dirent *e)
{
    return e->d_name[0] != '.';
}

/* Returns the names of the folders in `folder`, hidden ones left out, in strcmp's order;
 * sets *count. NULL (and errno) when the folder cannot be read. */
static char **list_folders(const char *folder, int *count)
{
    struct dirent **entries;
    int n = scandir(folder, &entries, visible, alphasort);
    if (n < 0)
        return NULL;
    char **names = grade_alloc(((size_t)n + 1) * sizeof *names);
    *count = 0;
    for (int k = 0; k < n; k++) {
        char *path = grade_format("%s/%s", folder, entries[k]->d_name);
        if (is_folder(path))
            names[(*count)++] = grade_copy(entries[k]->d_name);
        free(path);
        free(entries[k]);
    }
    free(entries);
    return names;
}

/* Frees the count names of a listing. */
static void free_names(char **names, int count)
{
    for (int k = 0; k < count; k++)
        free(names[k]);
    free(names);
}

/* Returns the folder of part `part`: a path, a folder of milestones/, or the one folder of
 * milestones/ whose name starts with "PART-"; NULL (reported) when there is none. */
static char *find_part(const char *top, const char *part)
{
    if (strchr(part, '/') != NULL) {
        char real[PATH_MAX];
        if (realpath(part, real) != NULL && is_folder(real))
            return grade_copy(real);
        fprintf(stderr, "grade: no part folder '%s'\n", part);
        return NULL;
    }
    char *milestones = grade_format("%s/milestones", top);
    int count = 0, matches = 0;
    char **names = list_folders(milestones, &count);
    char *found = NULL;
    size_t len = strlen(part);
    for (int k = 0; k < count; k++) {
        const char *name = names[k];
        if (strcmp(name, part) == 0) {
            matches = 1;
            free(found);
            found = grade_format("%s/%s", milestones, name);
            break;
        }
        if (strncmp(name, part, len) == 0 && name[len] == '-') {
            matches++;
            free(found);
            found = grade_format("%s/%s", milestones, name);
        }
    }
    if (matches != 1) {
        fprintf(stderr,
                "grade: %s part '%s' in %s; the parts are:", matches == 0 ? "no" : "more than one",
                part, milestones);
        for (int k = 0; k < count; k++)
            fprintf(stderr, " %s", names[k]);
        fputc('\n', stderr);
        free(found);
        found = NULL;
    }
    free_names(names, count);
    free(milestones);
    return found;
}

/* Returns raytra's option that `word` names (--name, --name=VALUE or -L), from the one
 * table of common/cli.c; NULL when none does. */
static const CliOption *option_of(const char *word)
{
    size_t len = strcspn(word + 2, "=");
    for (const CliOption *o = cli_options; o->name != NULL; o++)
        if (word[1] == '-' ? strlen(o->name) == len && strncmp(word + 2, o->name, len) == 0
                           : o->letter != 0 && word[1] == o->letter && word[2] == '\0')
            return o;
    return NULL;
}

/* Fills r->args with the words of a renders.txt line (words[0..n)) that students' programs
 * get: the positional words, and the value of an option the course gives as a positional
 * argument (1.4's MODE); raytra's own options are left out, with a note. */
static void keep_positional(Render *r, char **words, int n, int part, bool quiet)
{
    r->args = grade_alloc(((size_t)n + 1) * sizeof *r->args);
    int kept = 0;
    for (int k = 0; k < n; k++) {
        if (words[k][0] != '-' || words[k][1] == '\0') {
            r->args[kept++] = grade_copy(words[k]);
            continue;
        }
        const CliOption *o = option_of(words[k]);
        const char *eq = strchr(words[k], '=');
        bool next = o != NULL && o->kind != OPTION_FLAG && eq == NULL && k + 1 < n;
        const char *value = eq != NULL ? eq + 1 : next ? words[k + 1] : NULL;
        if (o != NULL && o->argument != NULL && value != NULL && cli_option_accepted(o, part))
            r->args[kept++] = grade_copy(value);
        else if (!quiet)
            fprintf(stderr,
                    "grade: note: %s: raytra's option %s%s%s is not given to students' "
                    "programs\n",
                    r->image, words[k], next ? " " : "", next ? words[k + 1] : "");
        k += next;
    }
}

/* Adds the render of a renders.txt line (its words) to g; false (reported) when the line
 * is not a valid one or names a file that is not there. */
static bool add_render(Grading *g, const char *top, char **words, int n, const char *where,
                       bool quiet)
{
    const char *image = words[0];
    const char *dot = strrchr(image, '.');
    if (image[0] == '!') {
        /* An illustration: raytra's own picture (an option students do not have, a
         * robustness case), which the references keep but no student is graded on. */
        char *more =
            grade_format("%s%s%.*s", g->illustrations != NULL ? g->illustrations : "",
                         g->illustrations != NULL ? ", " : "",
                         dot != NULL ? (int)(dot - image - 1) : (int)strlen(image + 1), image + 1);
        free(g->illustrations);
        g->illustrations = more;
        return true;
    }
    if (n < 2 || strchr(image, '/') != NULL || dot == NULL ||
        (strcmp(dot, ".png") != 0 && strcmp(dot, ".pfm") != 0 && strcmp(dot, ".exr") != 0)) {
        fprintf(stderr,
                "grade: %s: expected IMAGE SCENE [options], IMAGE a .png, .pfm or .exr name\n",
                where);
        return false;
    }
    Render *r = &g->renders[g->render_count];
    *r = (Render){.image = grade_copy(image), .scene = grade_copy(words[1])};
    r->name = grade_format("%.*s", (int)(dot - image), image);
    r->scene_path =
        words[1][0] == '/' ? grade_copy(words[1]) : grade_format("%s/%s", top, words[1]);
    r->reference = grade_format("%s/%s", g->references, image);
    keep_positional(r, words + 2, n - 2, cli_part_number(g->part), quiet);
    g->render_count++;
    if (!is_file(r->scene_path)) {
        fprintf(stderr, "grade: %s: no scene file %s\n", where, r->scene_path);
        return false;
    }
    if (!is_file(r->reference)) {
        fprintf(stderr, "grade: %s: no reference image %s (make references makes it)\n", where,
                r->reference);
        return false;
    }
    return true;
}

/* Reads references/renders.txt into g->renders; false (reported) when it cannot. */
static bool read_renders(Grading *g, const char *top, bool quiet)
{
    char *path = grade_format("%s/renders.txt", g->references);
    FILE *f = fopen(path, "r");
    if (f == NULL) {
        fprintf(stderr, "grade: cannot read %s: %s\n", path, strerror(errno));
        free(path);
        return false;
    }
    char *line = NULL;
    size_t size = 0;
    int line_number = 0, capacity = 0;
    bool ok = true;
    while (ok && getline(&line, &size, f) >= 0) {
        line_number++;
        char *words[64], *save = NULL;
        int n = 0;
        for (char *w = strtok_r(line, " \t\r\n", &save); w != NULL && n < 64;
             w = strtok_r(NULL, " \t\r\n", &save))
            words[n++] = w;
        if (n == 0 || words[0][0] == '#')
            continue;
        if (g->render_count == capacity) {
            capacity = capacity * 2 + 8;
            Render *grown = grade_alloc((size_t)capacity * sizeof *grown);
            if (g->render_count > 0)
                memcpy(grown, g->renders, (size_t)g->render_count * sizeof *grown);
            free(g->renders);
            g->renders = grown;
        }
        char *where = grade_format("%s:%d", path, line_number);
        ok = add_render(g, top, words, n, where, quiet);
        free(where);
    }
    free(line);
    fclose(f);
    if (ok && g->render_count == 0) {
        fprintf(stderr, "grade: %s lists no images\n", path);
        ok = false;
    }
    free(path);
    return ok;
}

/* Runs a command of the grader's own (no limits but time); true when it succeeds. */
static bool run_quietly(char **argv, const char *log)
{
    RunSpec spec = {.log = log, .time_limit = 600};
    RunResult r = run_program(argv, &spec);
    return r.end == RUN_EXITED && r.status == 0;
}

/* Makes folder path if it is not there; false (reported) when it cannot. */
static bool make_folder(const char *path)
{
    if (mkdir(path, 0777) == 0 || (errno == EEXIST && is_folder(path)))
        return true;
    fprintf(stderr, "grade: cannot make the folder %s: %s\n", path, strerror(errno));
    return false;
}

/* Makes OUT and an empty OUT/work (an absolute path), removing a work folder of an earlier run (one
 * holding the mark this writes) and refusing to remove any other; false (reported) on trouble. */
static bool prepare_work(Grading *g)
{
    char real[PATH_MAX];
    if (!make_folder(g->out))
        return false;
    /* Absolute: students' programs run in folders of their own. */
    if (realpath(g->out, real) == NULL) {
        fprintf(stderr, "grade: cannot find %s: %s\n", g->out, strerror(errno));
        return false;
    }
    g->work = grade_format("%s/work", real);
    char *mark = grade_format("%s/.made-by-grade", g->work);
    bool ok = true;
    if (is_folder(g->work) && !is_file(mark)) {
        fprintf(stderr, "grade: %s exists and was not made by grade: choose another --out\n",
                g->work);
        ok = false;
    } else if (is_folder(g->work)) {
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
    if (ok && (!make_folder(g->work) || (f = fopen(mark, "w")) == NULL))
        ok = false;
    if (f != NULL) {
        fprintf(f, "grade's work folder: each run of grade with this --out removes it and "
                   "makes it anew.\n");
        ok = fclose(f) == 0;
    }
    char *refs = grade_format("%s/references", g->work);
    ok = ok && make_folder(refs);
    free(refs);
    free(mark);
    return ok;
}

/* Prints the first line of the file at path to stderr after prefix, if there is one. */
static void print_first_line(const char *prefix, const char *path)
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
        print_first_line("grade: ", log);
        fprintf(stderr, "grade: imgdiff (%s) refused the tolerances or could not run\n",
                g->imgdiff);
    }
    free(log);
    return ok;
}

/* Makes the reference images' thumbnails; false (reported) when one cannot be read. */
static bool show_references(Grading *g)
{
    for (int k = 0; k < g->render_count; k++) {
        Render *r = &g->renders[k];
        r->reference_show = grade_format("%s/references/%s.png", g->work, r->name);
        char *log = grade_format("%s/references/%s.log", g->work, r->name);
        bool ok = thumb_make(r->reference, r->reference_show, THUMB_SIDE, THUMB_MEAN, log, 0);
        if (!ok && !stop_requested()) {
            fprintf(stderr, "grade: cannot read the reference image %s:\n", r->reference);
            print_first_line("    ", log);
        }
        free(log);
        if (!ok)
            return false;
    }
    return true;
}

/* Returns name with every byte but letters, digits, '.', '_' and '-' made '_', cut to 40
 * bytes: a work folder's name that a student's Makefile or script cannot trip on. */
static char *safe_name(const char *name)
{
    char *safe = grade_format("%.40s", name);
    for (char *p = safe; *p != '\0'; p++)
        if (!((*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') || (*p >= '0' && *p <= '9') ||
              *p == '.' || *p == '_' || *p == '-'))
            *p = '_';
    return safe;
}

/* Tells whether folder holds a Makefile, as make looks for one. */
static bool has_makefile(const char *folder)
{
    static const char *const names[] = {"GNUmakefile", "makefile", "Makefile"};
    bool found = false;
    for (size_t k = 0; k < sizeof names / sizeof names[0] && !found; k++) {
        char *path = grade_format("%s/%s", folder, names[k]);
        found = is_file(path);
        free(path);
    }
    return found;
}

/* Lists the submissions: the folders in g->submissions but hidden ones and the output
 * folder, in the order of their names; false (reported) when there are none. */
static bool list_submissions(Grading *g, bool self)
{
    int count = 0;
    char **names = NULL;
    if (self) {
        /* One student's folder: it is the one submission, named as the folder. */
        const char *end = g->submissions + strlen(g->submissions);
        while (end > g->submissions + 1 && end[-1] == '/')
            end--;
        const char *start = end;
        while (start > g->submissions && start[-1] != '/')
            start--;
        g->subs = grade_alloc(sizeof *g->subs);
        Submission *s = &g->subs[g->sub_count++];
        s->name = grade_format("%.*s", (int)(end - start), start);
        s->path = grade_copy(g->submissions);
        s->work = grade_format("%s/1-self", g->work);
        s->program = has_makefile(s->path);
        return true;
    }
    names = list_folders(g->submissions, &count);
    if (names == NULL) {
        fprintf(stderr, "grade: cannot read the folder %s: %s\n", g->submissions, strerror(errno));
        return false;
    }
    char out_real[PATH_MAX], real[PATH_MAX];
    if (realpath(g->out, out_real) == NULL)
        out_real[0] = '\0';
    g->subs = grade_alloc((size_t)count * sizeof *g->subs);
    int digits = count < 100 ? 2 : count < 1000 ? 3 : 6;
    for (int k = 0; k < count; k++) {
        char *path = grade_format("%s/%s", g->submissions, names[k]);
        if (realpath(path, real) != NULL && strcmp(real, out_real) == 0) {
            free(path);
            continue;
        }
        Submission *s = &g->subs[g->sub_count++];
        char *safe = safe_name(names[k]);
        s->name = grade_copy(names[k]);
        s->path = path;
        s->work = grade_format("%s/%0*d-%s", g->work, digits, g->sub_count, safe);
        s->program = has_makefile(s->path);
        char target[PATH_MAX];
        ssize_t n = readlink(s->path, target, sizeof target - 1);
        if (n >= 0)
            s->link = grade_format("%.*s", (int)n, target);
        free(safe);
    }
    free_names(names, count);
    if (g->sub_count == 0) {
        fprintf(stderr, "grade: no submissions in %s: it should hold a folder a student\n",
                g->submissions);
        return false;
    }
    return true;
}

/* Prints text to stderr with control characters made '?', so that a folder's name cannot
 * play tricks on the terminal. */
static void print_plain(const char *text)
{
    for (const char *p = text; *p != '\0'; p++)
        fputc((unsigned char)*p < 0x20 || *p == 0x7F ? '?' : *p, stderr);
}

/* Prints how the scenes of s went: "5 scenes: 4 pass, 1 timeout". */
static void print_tally(const Grading *g, const Submission *s)
{
    if (s->build_message[0] != '\0') {
        fprintf(stderr, "BUILD FAILED: %s\n", s->build_message);
        return;
    }
    fprintf(stderr, "%d scene%s:", g->render_count, g->render_count == 1 ? "" : "s");
    const char *sep = " ";
    for (int v = 0; v < VERDICT_COUNT; v++)
        if (s->verdicts[v] > 0) {
            fprintf(stderr, "%s%d ", sep, s->verdicts[v]);
            for (const char *p = verdict_name((Verdict)v); *p != '\0'; p++)
                fputc(*p >= 'A' && *p <= 'Z' ? *p - 'A' + 'a' : *p, stderr);
            sep = ", ";
        }
    fputc('\n', stderr);
}

/* Grades every submission, telling the progress unless quiet; false when interrupted
 * or when the grader itself failed (reported). */
static bool grade_all(Grading *g, bool quiet)
{
    for (int k = 0; k < g->sub_count; k++) {
        Submission *s = &g->subs[k];
        if (!quiet) {
            fprintf(stderr, "grading ");
            print_plain(s->name);
            fprintf(stderr, " (%s): %s", s->program ? "program" : "images",
                    s->program ? "building... " : "");
        }
        if (!submission_grade(g, s)) {
            if (!quiet)
                fputc('\n', stderr);
            return false;
        }
        if (!quiet)
            print_tally(g, s);
    }
    return true;
}

/* Prints, for a student checking their own work, each scene's verdict and reason, and the
 * heat map to look at when it did not pass; returns the exit status: 0 when every scene
 * passes, 1 otherwise. */
static int print_self(const Grading *g)
{
    const Submission *s = &g->subs[0];
    for (int k = 0; k < g->render_count; k++) {
        const SceneResult *res = &s->results[k];
        char *heat = grade_format("%s/%s.heat.png", s->work, g->renders[k].name);
        printf("%-12s %s: %s\n", verdict_name(res->verdict), g->renders[k].name, res->message);
        if (res->verdict != VERDICT_PASS && access(heat, F_OK) == 0)
            printf("%12s heat map: %s\n", "", heat);
        free(heat);
    }
    printf("%d of %d scenes pass; the report: %s/report.html\n", s->tally[TALLY_PASS],
           g->render_count, g->out);
    return s->tally[TALLY_PASS] == g->render_count ? 0 : 1;
}

/* Writes report.html and grades.csv into g->out; false (reported) when it cannot. */
static bool write_results(const Grading *g, bool quiet)
{
    char *csv = grade_format("%s/grades.csv", g->out);
    char *html = grade_format("%s/report.html", g->out);
    Error err;
    bool ok = report_write_csv(g, csv, &err);
    if (!ok)
        fprintf(stderr, "grade: cannot write %s: %s\n", csv, err.text);
    else if (!(ok = report_write_html(g, html, &err)))
        fprintf(stderr, "grade: cannot write %s: %s\n", html, err.text);
    else if (!quiet)
        fprintf(stderr, "grade: wrote %s and %s\n", html, csv);
    free(csv);
    free(html);
    return ok;
}

/* Does all the grading but reading the command line; returns the exit status. */
static int grade(const GradeOptions *o, Grading *g, const char *argv0)
{
    char *tools_build = NULL;
    char *top = find_top(argv0, &tools_build);
    char *part_dir = top != NULL ? find_part(top, o->part) : NULL;
    int status = EXIT_TROUBLE;
    if (part_dir == NULL)
        goto done;
    g->part = strrchr(part_dir, '/') + 1;
    g->references = grade_format("%s/references", part_dir);
    g->imgdiff = grade_format("%s/imgdiff", tools_build);
    g->out = o->out != NULL ? grade_copy(o->out) : grade_format("grading-%s", g->part);
    time_t now = time(NULL);
    strftime(g->started, sizeof g->started, "%Y-%m-%d %H:%M", localtime(&now));
    if (access(g->imgdiff, X_OK) != 0) {
        fprintf(stderr, "grade: no imgdiff at %s (make -C tools builds it)\n", g->imgdiff);
        goto done;
    }
    if (!is_folder(o->submissions)) {
        fprintf(stderr, "grade: no folder %s\n", o->submissions);
        goto done;
    }
    if (!read_renders(g, top, o->quiet) || !prepare_work(g) || !check_imgdiff(g) ||
        !show_references(g) || !list_submissions(g, o->self))
        goto done;
    if (!o->quiet)
        fprintf(stderr, "grade: part %s, %d scene%s, %d submission%s\n", g->part, g->render_count,
                g->render_count == 1 ? "" : "s", g->sub_count, g->sub_count == 1 ? "" : "s");
    if (!o->quiet && g->illustrations != NULL)
        fprintf(stderr, "grade: not graded (illustrations): %s\n", g->illustrations);
    if (grade_all(g, o->quiet) && write_results(g, o->quiet))
        status = o->self ? print_self(g) : EXIT_REPORTED;
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
    GradeOptions o;
    if (!parse_args(argc, argv, &o))
        return EXIT_TROUBLE;
    if (o.help) {
        print_help(stdout);
        return EXIT_REPORTED;
    }
    run_init();
    /* Static: what grading gathers lives until the exit, which frees it. */
    static Grading g;
    g = (Grading){.submissions = o.submissions,
                  .threshold = o.threshold,
                  .allow = o.allow,
                  .time_limit = o.time_limit,
                  .build_time_limit = o.build_time_limit,
                  .memory_limit = o.memory_limit};
    return grade(&o, &g, argv[0]);
}
