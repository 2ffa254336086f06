/* grade_renders.c: renders.txt read: each line's image, scene, judgement and a student's command line. */
#include "grade_renders.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "array.h"
#include "cli.h"
#include "grade_base.h"
#include "grade_path.h"
#include "image.h"
#include "lex.h"
#include "part_options.h"

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
bool renders_read(Grading *g)
{
    return read_renders(g, grade_format("%s/renders.txt", g->references), g->top, g->references);
}

/* Reads the renders.txt of the hidden scenes' folder (g->hidden) into g->renders, their
 * references rendered later (part_render_hidden); false (reported) when it cannot. */
bool renders_read_hidden(Grading *g)
{
    return read_renders(g, grade_format("%s/renders.txt", g->hidden), g->hidden, NULL);
}
