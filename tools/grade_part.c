/* grade_part.c: what grading reads first: the part's folder and its renders.txt. */
#include "grade.h"

#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "array.h"
#include "cli.h"
#include "image.h"
#include "lex.h"
#include "part_options.h"

/* Finds the folder of part `part`, g->part, and its references: a path, or the folder of
 * milestones/ named so or whose name starts with "PART-" (the first in the order of their
 * names, so that an exact name wins); false (reported) when there is none. */
bool part_find(Grading *g, const char *part)
{
    char real[PATH_MAX], *milestones = grade_format("%s/milestones", g->top), *all = "";
    char *found = NULL;
    if (strchr(part, '/') != NULL && realpath(part, real) != NULL && grade_kind(real) == S_IFDIR)
        found = grade_format("%s", real);
    int count = 0;
    char **names = grade_list_folders(milestones, &count);
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

/* Adds the render of a renders.txt line (its words) to g, or its name to the illustrations
 * (marked '!': raytra's own pictures, graded on no student); false (reported) when the line
 * is not a valid one or names a file that is not there. */
static bool add_render(Grading *g, char **words, int n, const char *where)
{
    /* ~IMAGE: a Monte Carlo render, judged against its statistical reference NAME.stats.exr. */
    bool statistical = words[0][0] == '~';
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
    Render *r = &g->renders[g->render_count++];
    *r = (Render){.image = grade_format("%s", image), .scene = grade_format("%s", words[1])};
    r->name = grade_format("%.*s", stem, image);
    r->reference = statistical ? grade_format("%s/%.*s.stats.exr", g->references, stem, image)
                               : grade_format("%s/%s", g->references, image);
    char *scene_path = words[1][0] == '/' ? r->scene : grade_format("%s/%s", g->top, words[1]);
    make_argv(r, scene_path, words + 2, n - 2, part_options_of(g->part), g->progress);
    if (grade_kind(scene_path) != S_IFREG)
        return grade_fail("%s: no scene file %s", where, scene_path);
    return grade_kind(r->reference) == S_IFREG ||
           grade_fail("%s: no reference image %s (make references makes it)", where, r->reference);
}

/* Reads references/renders.txt into g->renders; false (reported) when it cannot. */
bool part_read_renders(Grading *g)
{
    char *path = grade_format("%s/renders.txt", g->references), *line = NULL;
    FILE *f = fopen(path, "r");
    size_t size = 0;
    int line_number = 0, capacity = 0;
    bool ok = f != NULL || grade_fail("cannot read %s: %s", path, strerror(errno));
    while (ok && getline(&line, &size, f) >= 0) {
        line_number++;
        Words w;
        lex_split(line, &w);
        int n = w.count < LEX_MAX_WORDS ? w.count : LEX_MAX_WORDS;
        if (n == 0 || w.word[0][0] == '#')
            continue;
        char *where = grade_format("%s:%d", path, line_number);
        ok = (array_grow(&g->renders, &capacity, g->render_count, sizeof *g->renders) ||
              grade_fail("%s: out of memory", where)) &&
             add_render(g, w.word, n, where);
    }
    ok = ok && (g->render_count > 0 || grade_fail("%s lists no images", path));
    free(line);
    if (f != NULL)
        fclose(f);
    return ok;
}
