/* grade_diagnose.c: a failing image told which known mistake of its part it most resembles, or that none clearly does. */
#include "grade_diagnose.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "grade_base.h"
#include "grade_path.h"
#include "grade_run.h"
#include "image_read.h"

/* One known mistake of the part (grader/mistakes/PART.txt): its name, what it is in words,
 * and the folder of its renders of the part's scenes (grader/mistakes/render.sh). */
typedef struct {
    char *name, *title, *renders;
} Mistake;

/* The part's known mistakes, read once a process (each worker forks from the grader). */
static Mistake *mistakes;
static int mistake_count = -1;

/* Reads the catalogue of g's part, keeping the mistakes whose renders are there. */
static void diagnose_load(const Grading *g)
{
    mistake_count = 0;
    const char *build = strrchr(g->imgdiff, '/');
    int len = (int)(build - g->imgdiff), from = len;
    while (from > 0 && g->imgdiff[from - 1] != '/')
        from--; /* imgdiff is in compare/BUILD/: the renders are in grader/BUILD/mistakes/ */
    char *renders = grade_format("%s/grader/%.*s/mistakes/%s", g->top, len - from,
                                 g->imgdiff + from, g->part);
    FILE *f = fopen(grade_format("%s/grader/mistakes/%s.txt", g->top, g->part), "r");
    char line[1024];
    while (f != NULL && fgets(line, sizeof line, f) != NULL) {
        char name[128], program[512];
        int title = 0;
        line[strcspn(line, "\n")] = '\0';
        if (line[0] == '#' || sscanf(line, "%127s %511s %n", name, program, &title) != 2 ||
            line[title] == '\0')
            continue;
        char *folder = grade_format("%s/%s", renders, name);
        if (path_kind(folder) != S_IFDIR)
            continue;
        mistakes = realloc(mistakes, (size_t)(mistake_count + 1) * sizeof *mistakes);
        if (mistakes == NULL)
            abort();
        mistakes[mistake_count++] =
            (Mistake){grade_format("%s", name), grade_format("%s", line + title), folder};
    }
    if (f != NULL)
        fclose(f);
}

/* Returns the PSNR in dB of image against the file `against` (imgdiff --machine), at most
 * DIAGNOSE_EQUAL for equal images; NAN when they cannot be compared (a size differs). */
static double psnr_of(const Grading *g, const char *image, const char *against)
{
    char *argv[] = {g->imgdiff, "--machine", "--", (char *)against, (char *)image, NULL};
    RunResult run = run_program(argv, NULL, NULL, 600, RUN_OWN_MEMORY(g->memory_limit));
    const char *line = strstr(run.output, "psnr ");
    double psnr = NAN;
    if (run.end == RUN_EXITED && run.status <= 1 && line != NULL &&
        (line == run.output || line[-1] == '\n'))
        psnr = strtod(line + 5, NULL);
    return psnr > DIAGNOSE_EQUAL ? DIAGNOSE_EQUAL : psnr;
}

/* Returns where image differs from reference, coarsely: the absolute differences summed over
 * squares of DIAGNOSE_BLOCK pixels, a value a square into *count (malloc'd); NULL when
 * either cannot be read, their sizes differ, or memory is short. */
static double *block_errors(const Image *image, const char *reference, int *count)
{
    Image ref = {0};
    Error err;
    double *blocks = NULL;
    if (image->pixels != NULL && image_read(&ref, reference, &err) &&
        ref.width == image->width && ref.height == image->height) {
        int across = (ref.width + DIAGNOSE_BLOCK - 1) / DIAGNOSE_BLOCK;
        *count = across * ((ref.height + DIAGNOSE_BLOCK - 1) / DIAGNOSE_BLOCK);
        blocks = calloc((size_t)*count, sizeof *blocks); /* freed by its caller */
        for (long p = 0; blocks != NULL && p < (long)ref.width * ref.height; p++) {
            double *b = &blocks[p / ref.width / DIAGNOSE_BLOCK * across +
                                p % ref.width / DIAGNOSE_BLOCK];
            for (int c = 0; c < 3; c++) {
                double d = fabs((double)image->pixels[3 * p + c] - ref.pixels[3 * p + c]);
                *b += isfinite(d) ? d : 1;
            }
        }
    }
    image_free(&ref);
    return blocks;
}

/* Returns the cosine of the angle between a and b, of count values: 1 when the differences
 * fall in the same squares in the same proportions, 0 when in none alike; NAN for none. */
static double similarity(const double *a, const double *b, int count)
{
    double ab = 0, aa = 0, bb = 0;
    for (int k = 0; k < count; k++)
        ab += a[k] * b[k], aa += a[k] * a[k], bb += b[k] * b[k];
    return aa > 0 && bb > 0 ? ab / sqrt(aa * bb) : NAN;
}

/* Fills like[m] with how alike the squares where image (at path) differs from reference
 * and those where mistake m's render differs from it are (similarity); NAN when unknown. */
static void likeness(const char *path, const char *reference, char *const *renders,
                     double *like)
{
    Image image = {0}, mistake = {0};
    Error err;
    int count = 0, n = 0;
    double *own = image_read(&image, path, &err) ? block_errors(&image, reference, &count) : NULL;
    for (int m = 0; m < mistake_count; m++) {
        like[m] = NAN;
        if (own != NULL && renders[m] != NULL && image_read(&mistake, renders[m], &err)) {
            double *theirs = block_errors(&mistake, reference, &n);
            if (theirs != NULL && n == count)
                like[m] = similarity(own, theirs, count);
            free(theirs);
        }
        image_free(&mistake);
    }
    free(own);
    image_free(&image);
}

/* Chooses by where the differences fall (likeness): the mistake whose render differs from
 * the reference most as image does, when at least DIAGNOSE_ALIKE and DIAGNOSE_ALIKE_OVER
 * above every other's; else -1. */
int diagnose_choose_alike(const double *like, int count)
{
    int best = -1;
    for (int m = 0; m < count; m++)
        if (!isnan(like[m]) && (best < 0 || like[m] > like[best]))
            best = m;
    if (best < 0 || like[best] < DIAGNOSE_ALIKE)
        return -1;
    for (int m = 0; m < count; m++)
        if (m != best && !isnan(like[m]) && like[m] > like[best] - DIAGNOSE_ALIKE_OVER)
            return -1;
    return best;
}

/* Chooses among the candidates' PSNRs (of image to each mistake's render, and to the
 * reference): the nearest mistake when it is clearly nearest, else -1. Clearly: at least
 * DIAGNOSE_NEAR dB, DIAGNOSE_OVER_REFERENCE above the reference and DIAGNOSE_OVER_NEXT above
 * every other mistake whose render differs from it. */
int diagnose_choose(const double *psnr, int count, double reference)
{
    int best = -1;
    for (int m = 0; m < count; m++)
        if (!isnan(psnr[m]) && (best < 0 || psnr[m] > psnr[best]))
            best = m;
    if (best < 0 || psnr[best] < DIAGNOSE_NEAR ||
        !(isnan(reference) || psnr[best] >= reference + DIAGNOSE_OVER_REFERENCE))
        return -1;
    for (int m = 0; m < count; m++)
        if (m != best && !isnan(psnr[m]) && psnr[m] > psnr[best] - DIAGNOSE_OVER_NEXT)
            return -1;
    return best;
}

/* Returns the largest of values but the one at best; 0 when there is none. */
static double diagnose_next(const double *values, int count, int best)
{
    double next = 0;
    for (int m = 0; m < count; m++)
        if (m != best && !isnan(values[m]) && values[m] > next)
            next = values[m];
    return next;
}

/* Appends to res's message which known mistake of the part image, failing render k, most
 * resembles: for a render judged against the program's own OTHER (IMAGE=OTHER), image is
 * the program's OTHER, the image that tells; nothing when the part has no known mistake
 * rendered. */
void diagnose_scene(const Grading *g, const Submission *s, int k, const char *image)
{
    SceneResult *res = &s->results[k];
    if (res->verdict != VERDICT_FAIL || !res->compared)
        return;
    if (mistake_count < 0)
        diagnose_load(g);
    const Render *r = &g->renders[k];
    const char *name = r->image, *reference = r->statistical ? r->shipped : r->reference;
    if (r->judge == JUDGE_SAME_AS) {
        const Render *other = &g->renders[r->same_as];
        name = other->image, reference = other->reference;
    }
    double *psnr = grade_alloc((size_t)(mistake_count + 1) * 2 * sizeof *psnr),
           *like = psnr + mistake_count + 1;
    char **renders = grade_alloc((size_t)(mistake_count + 1) * sizeof *renders);
    int rendered = 0;
    for (int m = 0; m < mistake_count; m++) {
        renders[m] = grade_format("%s/%s", mistakes[m].renders, name);
        if (path_kind(renders[m]) != S_IFREG)
            renders[m] = NULL;
        psnr[m] = renders[m] != NULL ? psnr_of(g, image, renders[m]) : NAN;
        rendered += !isnan(psnr[m]);
    }
    if (rendered == 0 || reference == NULL)
        return;
    double to_reference = psnr_of(g, image, reference);
    int best = diagnose_choose(psnr, mistake_count, to_reference), alike = -1;
    /* A Monte Carlo image's squares differ by its noise everywhere: where it differs tells
     * little, and named another mistake than its own (docs/diagnosis.md). */
    if (best < 0 && !r->statistical) {
        likeness(image, reference, renders, like);
        alike = diagnose_choose_alike(like, mistake_count);
    }
    size_t used = strlen(res->message);
    if (best >= 0 && psnr[best] >= DIAGNOSE_EQUAL)
        snprintf(res->message + used, sizeof res->message - used,
                 "; closest to: %s (equal to that mistake's render; %.0f dB to the reference)",
                 mistakes[best].title, to_reference);
    else if (best >= 0)
        snprintf(res->message + used, sizeof res->message - used,
                 "; closest to: %s (%.0f dB to that mistake's render, %.0f dB to the "
                 "reference)",
                 mistakes[best].title, psnr[best], to_reference);
    else if (alike >= 0)
        snprintf(res->message + used, sizeof res->message - used,
                 "; closest to: %s (it differs from the reference where that mistake's render "
                 "does, alike at %.2f, the next mistake at most %.2f)",
                 mistakes[alike].title, like[alike], diagnose_next(like, mistake_count, alike));
    else
        snprintf(res->message + used, sizeof res->message - used,
                 "; no known mistake matches");
}
