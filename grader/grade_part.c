/* grade_part.c: what grading reads first: the part's folder and its renders.txt. */
#include "grade.h"

#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "array.h"
#include "cli.h"
#include "image.h"
#include "lex.h"
#include "part_options.h"
#include "stop.h"

/* Finds the top of the repository, g->top, two folders above the grader's program
 * (grader/build/grade), and imgdiff in compare/'s folder of the same build; false (reported)
 * when it is not there. */
bool part_find_top(Grading *g)
{
    char exe[PATH_MAX] = "", real[PATH_MAX];
    if (realpath("/proc/self/exe", exe) != NULL)
        *strrchr(exe, '/') = '\0';
    if (realpath(grade_format("%s/../../milestones", exe), real) == NULL ||
        path_kind(real) != S_IFDIR)
        return grade_fail("cannot find the raytra repository: the grader must stay in "
                          "grader/build/ of its checkout");
    g->top = grade_format("%.*s", (int)(strrchr(real, '/') - real), real);
    g->imgdiff = grade_format("%s/compare/%s/imgdiff", g->top, strrchr(exe, '/') + 1);
    return access(g->imgdiff, X_OK) == 0 ||
           grade_fail("no imgdiff at %s (make -C compare builds it)", g->imgdiff);
}

/* Finds the folder of part `part`, g->part, and its references: a path, or the folder of
 * milestones/ named so or whose name starts with "PART-" (the first in the order of their
 * names, so that an exact name wins); false (reported) when there is none. */
bool part_find(Grading *g, const char *part)
{
    char real[PATH_MAX], *milestones = grade_format("%s/milestones", g->top), *all = "";
    char *found = NULL;
    if (strchr(part, '/') != NULL && realpath(part, real) != NULL && path_kind(real) == S_IFDIR)
        found = grade_format("%s", real);
    int count = 0;
    char **names = path_list_folders(milestones, &count);
    size_t len = strlen(part);
    for (int k = 0; found == NULL && k < count; k++) {
        if (strncmp(names[k], part, len) == 0 && (names[k][len] == '\0' || names[k][len] == '-'))
            found = grade_format("%s/%s", milestones, names[k]);
        all = grade_format("%s %s", all, names[k]);
    }
    if (found == NULL)
        return grade_fail("no part '%s' in %s; the parts are:%s", part, milestones, all);
    g->part = strrchr(found, '/') + 1;
    g->references = grade_format("%s/references", found);
    return true;
}

/* Returns the option of raytra's part (its tables: part_options_of) that `word` names
 * (--name, --name=VALUE or -L); NULL when none does. */
static const CliOption *option_of(const CliOption *const *tables, const char *word)
{
    if (word[1] == '-')
        return cli_option_named(tables,
                                grade_format("%.*s", (int)strcspn(word + 2, "="), word + 2));
    return word[2] == '\0' ? cli_option_lettered(tables, word[1]) : NULL;
}

/* Returns the place of option o among the options of tables that the course gives as
 * positional arguments, in the order the course gives them (the tables' order): P is 0
 * and S 1 in part 1.6, whatever order a renders.txt line names them in. */
static int argument_place(const CliOption *const *tables, const CliOption *o)
{
    int place = 0;
    for (int t = 0; tables[t] != NULL; t++)
        for (const CliOption *c = tables[t]; c->name != NULL; c++) {
            if (c == o)
                return place;
            place += c->argument != NULL;
        }
    return place;
}

/* Makes r->argv, a student's command line, of the scene's path and the words of its
 * renders.txt line (words[0..n)) that students' programs get: the positional words, and
 * the values of the options the course gives as positional arguments (1.4's MODE, 1.6's
 * P and S), where the line names them, but among themselves in the course's order (P
 * before S, whatever order the line names them in); raytra's own options are left out,
 * with a note on `notes`. */
static void make_argv(Render *r, char *scene_path, char **words, int n,
                      const CliOption *const *tables, FILE *notes)
{
    r->argv = grade_alloc(((size_t)n + RENDER_WORDS + 1) * sizeof *r->argv);
    int *at = grade_alloc(((size_t)n + 1) * sizeof *at);
    int *place = grade_alloc(((size_t)n + 1) * sizeof *place);
    int options = 0;
    r->argv[1] = scene_path;
    int kept = RENDER_WORDS;
    for (int k = 0; k < n; k++) {
        const CliOption *o = words[k][0] == '-' ? option_of(tables, words[k]) : NULL;
        const char *eq = strchr(words[k], '=');
        bool next = o != NULL && o->kind != OPTION_FLAG && eq == NULL && k + 1 < n;
        const char *value = eq != NULL ? eq + 1 : next ? words[k + 1] : NULL;
        if (words[k][0] != '-' || words[k][1] == '\0')
            r->argv[kept++] = grade_format("%s", words[k]);
        else if (o != NULL && o->argument != NULL && value != NULL) {
            at[options] = kept, place[options++] = argument_place(tables, o);
            r->argv[kept++] = grade_format("%s", value);
        } else
            fprintf(notes, "grade: note: %s: raytra's option %s%s%s is not given to students' "
                           "programs\n",
                    r->image, words[k], next ? " " : "", next ? words[k + 1] : "");
        k += next;
    }
    /* The options' values sorted into the course's order, in the places they took. */
    for (int a = 1; a < options; a++)
        for (int b = a; b > 0 && place[b - 1] > place[b]; b--) {
            char *value = r->argv[at[b - 1]];
            int p = place[b - 1];
            r->argv[at[b - 1]] = r->argv[at[b]], place[b - 1] = place[b];
            r->argv[at[b]] = value, place[b] = p;
        }
}

/* Sets how render r, of a line IMAGE=OTHER or IMAGE>MASK (how: '=' or '>', `other` the name
 * after it), is judged: against the reference of OTHER, an earlier line, and then pixel for
 * pixel against the program's own image of OTHER; or by coverage of the reference MASK.
 * False (reported) when OTHER or MASK is not there. */
static bool judge_of(Grading *g, Render *r, char how, const char *other, const char *where)
{
    if (how == '>') {
        r->judge = JUDGE_COVER;
        r->mask = grade_format("%s/%s", g->references, other);
        return (strchr(other, '/') == NULL && path_kind(r->mask) == S_IFREG) ||
               grade_fail("%s: no reference image %s for %s to cover", where, r->mask, r->image);
    }
    r->judge = JUDGE_SAME_AS;
    for (int k = 0; k < g->render_count - 1; k++)
        if (strcmp(g->renders[k].image, other) == 0 && g->renders[k].judge == JUDGE_REFERENCE) {
            r->same_as = k;
            r->reference = g->renders[k].reference;
            return true;
        }
    return grade_fail("%s: %s=%s: no earlier line renders %s, judged against its reference", where,
                      r->image, other, other);
}

/* Adds the render of a renders.txt line (its words) to g, or its name to the illustrations
 * (marked '!': raytra's own pictures, graded on no student); scenes are read from `base`,
 * references from `references` (a hidden scene's: NULL, rendered later); false (reported)
 * when the line is not a valid one or names a file that is not there. */
static bool add_render(Grading *g, char **words, int n, const char *where, const char *base,
                       const char *references)
{
    /* ~IMAGE: a Monte Carlo render, judged against its statistical reference NAME.stats.exr. */
    bool statistical = words[0][0] == '~';
    /* IMAGE=OTHER and IMAGE>MASK: judged otherwise (judge_of); words[0] ends at IMAGE. */
    char *judged = strpbrk(words[0], "=>"), how = judged != NULL ? *judged : '\0';
    if (judged != NULL)
        *judged++ = '\0';
    const char *image = words[0] + statistical, *dot = strrchr(image, '.');
    int stem = dot != NULL ? (int)(dot - image) : (int)strlen(image);
    if (image[0] == '!') {
        g->illustrations = grade_format("%s%s%.*s", g->illustrations ? g->illustrations : "",
                                        g->illustrations ? ", " : "", stem - 1, image + 1);
        return true;
    }
    if (n < 2 || strchr(image, '/') != NULL || image_format_for_path(image) == IMAGE_FORMAT_UNKNOWN)
        return grade_fail("%s: expected IMAGE SCENE [options], IMAGE a .png, .pfm or .exr name",
                          where);
    if (references == NULL && statistical)
        return grade_fail("%s: a hidden scene cannot be a Monte Carlo render (~IMAGE)", where);
    for (int k = 0; k < g->render_count; k++)
        if (strncmp(g->renders[k].name, image, (size_t)stem) == 0 &&
            g->renders[k].name[stem] == '\0')
            return grade_fail("%s: a scene named %.*s is graded already", where, stem, image);
    Render *r = &g->renders[g->render_count++];
    *r = (Render){.image = grade_format("%s", image), .scene = grade_format("%s", words[1]),
                  .points = 1, .visibility = "visible", .hidden = references == NULL,
                  .statistical = statistical};
    r->name = grade_format("%.*s", stem, image);
    r->reference = r->hidden              ? NULL
                   : statistical          ? grade_format("%s/%.*s.stats.exr", references, stem, image)
                                          : grade_format("%s/%s", references, image);
    char *scene_path = words[1][0] == '/' ? r->scene : grade_format("%s/%s", base, words[1]);
    make_argv(r, scene_path, words + 2, n - 2, part_options_of(g->part), g->progress);
    /* The model answer renders a hidden scene's reference with every word of its line. */
    r->model = grade_alloc(((size_t)n + 2) * sizeof *r->model);
    r->model[1] = scene_path;
    for (int k = 2; k < n; k++)
        r->model[k + 1] = grade_format("%s", words[k]);
    if (path_kind(scene_path) != S_IFREG)
        return grade_fail("%s: no scene file %s", where, scene_path);
    if (judged != NULL && statistical)
        return grade_fail("%s: a Monte Carlo render (~) is judged by statistics alone", where);
    if (judged != NULL && r->hidden)
        return grade_fail("%s: a hidden scene is judged against its own reference alone", where);
    if (judged != NULL && !judge_of(g, r, how, judged, where))
        return false;
    r->shipped = r->hidden                    ? NULL
                 : r->judge == JUDGE_SAME_AS ? g->renders[r->same_as].shipped
                                             : grade_format("%s/%s", references, image);
    return r->hidden || path_kind(r->reference) == S_IFREG ||
           grade_fail("%s: no reference image %s (make references makes it)", where, r->reference);
}

/* Reads the renders.txt at path into g->renders, its scenes from `base`, its references
 * from `references` (NULL: hidden scenes); false (reported) when it cannot. */
static bool read_renders(Grading *g, const char *path, const char *base, const char *references)
{
    char *line = NULL, *why = NULL;
    FILE *f = fopen(path, "r");
    size_t size = 0;
    int line_number = 0, capacity = g->render_count, before = g->render_count;
    bool ok = f != NULL || grade_fail("cannot read %s: %s", path, strerror(errno));
    while (ok && getline(&line, &size, f) >= 0) {
        line_number++;
        /* #? TEXT: what a failure of the next line's judgement means, for the message. */
        const char *text = line + strspn(line, " \t");
        if (strncmp(text, "#?", 2) == 0) {
            text += 2 + strspn(text + 2, " \t");
            why = grade_format("%.*s", (int)strcspn(text, "\r\n"), text);
        }
        Words w;
        lex_split(line, &w);
        int n = w.count < LEX_MAX_WORDS ? w.count : LEX_MAX_WORDS, added_at = g->render_count;
        if (n == 0 || w.word[0][0] == '#')
            continue;
        char *where = grade_format("%s:%d", path, line_number);
        ok = (array_grow(&g->renders, &capacity, g->render_count, sizeof *g->renders) ||
              grade_fail("%s: out of memory", where)) &&
             add_render(g, w.word, n, where, base, references);
        if (ok && g->render_count > added_at)
            g->renders[added_at].why = why;
        why = NULL;
    }
    ok = ok && (g->render_count > before || grade_fail("%s lists no images", path));
    free(line);
    if (f != NULL)
        fclose(f);
    return ok;
}

/* Reads references/renders.txt into g->renders; false (reported) when it cannot. */
bool part_read_renders(Grading *g)
{
    return read_renders(g, grade_format("%s/renders.txt", g->references), g->top, g->references);
}

/* Returns the path p of a grading.conf line, from the folder `dir` of the file: as it is
 * when absolute, from HOME when it starts with "~/". */
static char *conf_path(const char *dir, const char *p)
{
    const char *home = getenv("HOME");
    if (strncmp(p, "~/", 2) == 0 && home != NULL)
        return grade_format("%s/%s", home, p + 2);
    return p[0] == '/' ? grade_format("%s", p) : grade_format("%s/%s", dir, p);
}

/* Tells whether text is one of Gradescope's visibilities of a test. */
static bool is_visibility(const char *text)
{
    static const char *const all[] = {"visible", "hidden", "after_due_date", "after_published"};
    for (size_t k = 0; k < sizeof all / sizeof all[0]; k++)
        if (strcmp(text, all[k]) == 0)
            return true;
    return false;
}

/* Reads a number of points, from 0 to 10000, into *v; false when the word is none. */
static bool read_points(const char *word, double *v)
{
    char *end;
    *v = strtod(word, &end);
    return end != word && *end == '\0' && *v >= 0 && *v <= 10000;
}

/* One scene line of grading.conf, kept until the hidden scenes are read: they may name one. */
typedef struct {
    char *name, *where, *visibility;
    double points;
} ConfScene;

/* Sets the points and visibility of the scenes a grading.conf line names: all of them for
 * "*" (the default: set first, so that later lines win), or the one of its name; false
 * (reported) when no scene has the name. */
static bool apply_scene(Grading *g, const ConfScene *c)
{
    bool found = false;
    for (int k = 0; k < g->render_count; k++) {
        Render *r = &g->renders[k];
        if (strcmp(c->name, "*") != 0 && strcmp(c->name, r->name) != 0)
            continue;
        r->points = c->points;
        r->visibility = c->visibility != NULL ? c->visibility : r->visibility;
        found = true;
    }
    return found || strcmp(c->name, "*") == 0 ||
           grade_fail("%s: no scene '%s' in renders.txt%s", c->where, c->name,
                      g->hidden != NULL ? grade_format(" or in %s/renders.txt", g->hidden)
                                        : " (a hidden scene? the hidden folder is not given)");
}

/* Reads grading.conf, the instructor's controls (docs/grading.md): the part's points
 * ("part N"), the folder of hidden scenes ("hidden DIR", unless --hidden names one), and
 * a line a scene, "NAME POINTS [VISIBILITY]", "*" for every scene not named. With no
 * grading.conf, every scene is worth 1 point and visible. Reads the hidden scenes' list
 * too. False (reported, as FILE:LINE: what is wrong) when a line is not right. */
bool part_read_conf(Grading *g)
{
    char *path = g->conf != NULL ? (char *)g->conf : grade_format("%s/grading.conf", g->references);
    const char *slash = strrchr(path, '/');
    char *dir = slash != NULL ? grade_format("%.*s", (int)(slash - path), path) : ".";
    char *line = NULL;
    FILE *f = fopen(path, "r");
    if (f == NULL && g->conf == NULL && errno == ENOENT)
        f = fmemopen("* 1\n", 4, "r");
    if (f == NULL)
        return grade_fail("cannot read %s: %s", path, strerror(errno));
    size_t size = 0;
    int line_number = 0, count = 0, part_line = 0;
    int capacity = 0;
    ConfScene *scenes = NULL;
    bool ok = true, part_seen = false;
    while (ok && getline(&line, &size, f) >= 0) {
        line_number++;
        Words w;
        lex_split(line, &w);
        int n = w.count < LEX_MAX_WORDS ? w.count : LEX_MAX_WORDS;
        char *where = grade_format("%s:%d", path, line_number);
        for (int k = 0; k < n; k++)
            if (w.word[k][0] == '#')
                n = k; /* a comment to the end of the line */
        if (n == 0)
            continue;
        if (strcmp(w.word[0], "part") == 0)
            ok = (n == 2 && !part_seen && read_points(w.word[1], &g->part_points) &&
                  g->part_points > 0) ||
                 grade_fail("%s: expected 'part POINTS', once: what the part is worth, more "
                            "than 0 (its scenes' points are scaled to it)", where);
        else if (strcmp(w.word[0], "hidden") == 0 && n == 2) {
            if (g->hidden == NULL)
                g->hidden = conf_path(dir, w.word[1]);
        } else if (strcmp(w.word[0], "hidden") == 0)
            ok = grade_fail("%s: expected 'hidden FOLDER': the folder of your own scenes", where);
        else if (n < 2 || n > 3)
            ok = grade_fail("%s: expected 'SCENE POINTS [VISIBILITY]', 'part POINTS' or "
                            "'hidden FOLDER'", where);
        else if (!read_points(w.word[1], &(double){0}))
            ok = grade_fail("%s: '%s' is not a number of points from 0 to 10000", where,
                            w.word[1]);
        else if (n == 3 && !is_visibility(w.word[2]))
            ok = grade_fail("%s: '%s' is not a visibility: visible, hidden, after_due_date or "
                            "after_published", where, w.word[2]);
        else if (!array_grow(&scenes, &capacity, count, sizeof *scenes))
            ok = grade_fail("%s: out of memory", where);
        else {
            ConfScene *c = &scenes[count++];
            *c = (ConfScene){.name = grade_format("%s", w.word[0]), .where = where,
                             .visibility = n == 3 ? grade_format("%s", w.word[2]) : NULL};
            read_points(w.word[1], &c->points);
        }
        if (strcmp(w.word[0], "part") == 0)
            part_seen = true, part_line = line_number;
    }
    free(line);
    fclose(f);
    if (ok && g->hidden != NULL)
        ok = (path_kind(g->hidden) == S_IFDIR || grade_fail("no folder of hidden scenes %s",
                                                            g->hidden)) &&
             read_renders(g, grade_format("%s/renders.txt", g->hidden), g->hidden, NULL);
    /* The defaults first: a hidden scene is shown once the due date has passed. */
    for (int k = 0; k < g->render_count; k++)
        g->renders[k].visibility = g->renders[k].hidden ? "after_due_date" : "visible";
    for (int pass = 0; pass < 2; pass++)
        for (int k = 0; ok && k < count; k++)
            if ((strcmp(scenes[k].name, "*") == 0) == (pass == 0))
                ok = apply_scene(g, &scenes[k]);
    free(scenes);
    double total = 0;
    for (int k = 0; k < g->render_count; k++)
        total += g->renders[k].points;
    return ok && (total > 0 || g->part_points == 0 ||
                  grade_fail("%s:%d: the part is worth %g points but its scenes are worth none",
                             path, part_line, g->part_points));
}

/* Returns what submission s scores, its scenes' points (scaled to the part's, when
 * grading.conf gives it), and sets *max to the most it could. */
double part_points(const Grading *g, const Submission *s, double *max)
{
    double got = 0, all = 0;
    for (int k = 0; k < g->render_count; k++) {
        all += g->renders[k].points;
        got += s->results[k].verdict == VERDICT_PASS ? g->renders[k].points : 0;
    }
    double scale = g->part_points > 0 && all > 0 ? g->part_points / all : 1;
    *max = all * scale;
    return got * scale;
}

/* Makes the references of the hidden scenes (--hidden): each one's DIR/references/IMAGE
 * when it is there (make gradescope renders them into its zip), or else rendered now by
 * the part's model answer (built first) into OUT/work/references/hidden; and copies the scenes
 * to OUT/work/hidden-scenes, readable by the grader alone but while one is rendered (DIR
 * itself may be readable by the grader's user alone, and its files' modes come along with
 * cp). False (reported) on trouble. */
bool part_render_hidden(Grading *g)
{
    char *part_dir = grade_format("%s/milestones/%s", g->top, g->part);
    char *scenes = grade_format("%s/hidden-scenes", g->work), *log = NULL;
    bool built = false, any = false;
    for (int k = 0; k < g->render_count; k++)
        any |= g->renders[k].hidden;
    if (!any)
        return true;
    char *copy[] = {"sh", "-c", "mkdir -- \"$2\" && cp -R -P -- \"$1/.\" \"$2\" && "
                                "rm -rf -- \"$2/references\" \"$2/renders.txt\" && "
                                "chmod -R go-rwx -- \"$2\" && "
                                "find \"$2\" -type d -exec chmod 711 {} +",
                    "sh", (char *)g->hidden, scenes, NULL};
    if (!run_program(copy, NULL, NULL, 600, 0).ok)
        return grade_fail("cannot copy the hidden scenes of %s to %s", g->hidden, scenes);
    for (int k = 0; k < g->render_count; k++) {
        Render *r = &g->renders[k];
        if (!r->hidden)
            continue;
        char *given = grade_format("%s/references/%s", g->hidden, r->image);
        /* The student's program reads the scene from the copy, named from its run folder
         * (work/NAME/run) so that its command line does not depend on where work is. */
        r->argv[1] = r->scene[0] == '/' ? r->scene
                                        : grade_format("../../hidden-scenes/%s", r->scene);
        if (path_kind(given) == S_IFREG) {
            r->reference = given;
            continue;
        }
        char *make[] = {"make", "--no-print-directory", "-s", "-C", part_dir, "SANITIZE=",
                        "raytra", NULL};
        log = grade_format("%s/references/model.log", g->work);
        if (!built && !run_program(make, NULL, log, 1800, 0).ok)
            return grade_fail("the model answer of %s does not build, to render the hidden "
                              "scenes (%s says why)", g->part, log);
        if (!built && !path_make_folder(grade_format("%s/references/hidden", g->work)))
            return false;
        built = true;
        r->reference = grade_format("%s/references/hidden/%s", g->work, r->image);
        r->model[0] = grade_format("%s/raytra", part_dir);
        r->model[2] = r->reference;
        fprintf(g->progress, "grade: rendering the hidden scene %s with the model answer\n",
                r->name);
        if (!run_program(r->model, NULL, log, 1800, 0).ok)
            return grade_fail("the model answer could not render the hidden scene %s (%s says "
                              "why)", r->name, log);
    }
    return true;
}

/* Has imgdiff compare each reference with itself before any work, which checks both the
 * image and the tolerances and makes the report's thumbnail; false (reported) on trouble. */
bool part_show_references(Grading *g)
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

/* Makes each PNG reference's canary (Render.canary), the file the grader puts in the place
 * of every copy of the shipped reference a submission carries: the reference's values with
 * one channel of one pixel in 32 (chosen by a number of this run) one code (1/255) off,
 * within the tolerance of a pass (imgdiff's threshold is at least 1/255). A program that
 * copies the reference it carries writes the canary's values, which no render writes,
 * however it re-encodes them; one that renders writes the reference's. The canaries are
 * written with gamma 1.0, the values as the file holds them, which is what imgdiff
 * compares; their folder is open to students' users for their build to put them in place
 * (plant_canaries), never seen by a program in namespaces. A reference that is not a PNG
 * gets none. */
void part_make_canaries(Grading *g)
{
    unsigned long key = (unsigned long)time(NULL) ^ ((unsigned long)getpid() << 16);
    chmod(grade_format("%s/canaries", g->work), 0755);
    for (int k = 0; k < g->render_count; k++) {
        Render *r = &g->renders[k];
        Image img;
        Error err;
        if (r->shipped == NULL || image_format_for_path(r->shipped) != IMAGE_FORMAT_PNG ||
            !image_read_png(&img, r->shipped, &err))
            continue;
        for (long p = 0; p < (long)img.width * img.height; p++) {
            unsigned long h = ((unsigned long)p * 2654435761UL) ^ key;
            h = (h ^ (h >> 15)) * 0x2C1B3C6DUL;
            h ^= h >> 12;
            if (h % 32 != 0)
                continue;
            float *v = img.pixels + 3 * p + (h >> 5) % 3;
            int code = (int)(*v * 255 + 0.5f);
            *v = (float)(code < 255 ? code + 1 : code - 1) / 255;
        }
        char *path = grade_format("%s/canaries/%s.canary.png", g->work, r->name);
        if (image_write(&img, path, PNG_ENCODING_LINEAR, &err) && chmod(path, 0644) == 0)
            r->canary = path;
        image_free(&img);
    }
}
