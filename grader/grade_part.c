/* grade_part.c: the part's folder found, its references made and shown, their canaries; what a submission scores. */
#include "grade_part.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "grade_base.h"
#include "grade_path.h"
#include "grade_run.h"
#include "image.h"
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
    /* Made anew: a regrade (--only) finds the earlier grading's copy there. */
    char *copy[] = {"sh", "-c", "chmod -R u+rwX -- \"$2\" 2>/dev/null; rm -rf -- \"$2\" && "
                                "mkdir -- \"$2\" && cp -R -P -- \"$1/.\" \"$2\" && "
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
        char *rendered = grade_format("%s/references/hidden", g->work);
        if (!built && path_kind(rendered) != S_IFDIR && !path_make_folder(rendered))
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
