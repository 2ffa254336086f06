/* grade_conf.c: grading.conf read: the part's points, its hidden scenes, each scene's points and visibility. */
#include "grade_conf.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "array.h"
#include "grade_base.h"
#include "grade_late.h"
#include "grade_path.h"
#include "grade_renders.h"
#include "lex.h"

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
 * ("part N"), the folder of hidden scenes ("hidden DIR", unless --hidden names one), the
 * lines of late work (late_conf_line), and a line a scene, "NAME POINTS [VISIBILITY]", "*"
 * for every scene not named. With no
 * grading.conf, every scene is worth 1 point and visible. Reads the hidden scenes' list
 * too. False (reported, as FILE:LINE: what is wrong) when a line is not right. */
bool conf_read(Grading *g)
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
    unsigned late_seen = 0;
    while (ok && getline(&line, &size, f) >= 0) {
        line_number++;
        Words w;
        lex_split(line, &w);
        int n = w.count < LEX_MAX_WORDS ? w.count : LEX_MAX_WORDS;
        char *where = grade_format("%s:%d", path, line_number);
        for (int k = 0; k < n; k++)
            if (w.word[k][0] == '#')
                n = k; /* a comment to the end of the line */
        if (n == 0 || late_conf_line(g, w.word, n, where, &late_seen, &ok))
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
             renders_read_hidden(g);
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
