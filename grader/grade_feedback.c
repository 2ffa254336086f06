/* grade_feedback.c: a scene's verdict told to a student, for JUnit and Gradescope: why, its figures, what to do. */
#include "grade_feedback.h"

#include <math.h>
#include <string.h>

#include "grade_base.h"
#include "grade_run.h"
#include "grade_verdict.h"

/* Returns imgdiff's figures for a scene, in a sentence, as the report gives them: "" when
 * no comparison was made. */
static char *figures_text(const SceneResult *res)
{
    const Figures *f = &res->figures;
    if (!res->compared)
        return "";
    return grade_format(
        "Max diff R, G, B: %.3g, %.3g, %.3g /255; mean abs diff %.3g /255; RMSE %.4g; PSNR %s; "
        "differing pixels: %ld of %ld (%.3g%%)%s.\n",
        f->max[0] * 255, f->max[1] * 255, f->max[2] * 255, f->mean * 255, f->rmse,
        isinf(f->psnr) ? "infinite (equal)" : grade_format("%.2f dB", f->psnr), f->differing,
        f->pixels, 100.0 * f->differing / (f->pixels > 0 ? (double)f->pixels : 1),
        f->differing > 0 ? grade_format(", in the box (%d,%d)-(%d,%d), y from the top", f->box[0],
                                        f->box[1], f->box[2], f->box[3])
                         : "");
}

/* Returns the command line that renders r from the top of a student's folder, as
 * the starter lays it out: ./raytra SCENE IMAGE [positional arguments]. */
static char *student_command(const Render *r)
{
    int n = 0;
    while (r->argv[RENDER_WORDS + n] != NULL)
        n++;
    char **argv = grade_alloc(((size_t)n + RENDER_WORDS + 1) * sizeof *argv);
    argv[0] = "./raytra";
    argv[1] = r->scene;
    argv[2] = r->image;
    memcpy(argv + RENDER_WORDS, r->argv + RENDER_WORDS, (size_t)n * sizeof *argv);
    return run_command_line(argv, NULL);
}

/* Returns what a student does about a scene's verdict: a sentence or two, concrete, naming
 * the file or the command to look at; "" for a pass. A hidden scene (r->hidden), which the
 * student does not have, gets advice that names no scene file and no command to run it. */
static char *advice(const Grading *g, const Render *r, const SceneResult *res)
{
    switch (res->verdict) {
    case VERDICT_PASS: return "";
    case VERDICT_FAIL:
        if (r->hidden)
            return "This scene is not in your starter, so you cannot render it yourself: run "
                   "`make check` on the starter's scenes, and look for what your program gets "
                   "right there only because of how they are arranged (the camera, the lights, "
                   "where the objects lie). Look at the box above first.";
        return grade_format("Render the scene with the command below and compare it with the "
                            "reference: `make check` in your starter writes its heat map to "
                            "out/check/%s.heat.png, black where the images agree and bright "
                            "where they differ. Look at the box above first.",
                            r->name);
    case VERDICT_WRONG_SIZE:
        return "Write the image at the size the scene file gives (its camera's width and "
               "height), whatever the options say.";
    case VERDICT_LINK:
        return "Hand in the program and let it write its images: a link is not an image.";
    case VERDICT_UNREADABLE:
        return "Write a PNG file at the path raytra gets as its second argument, with the "
               "image functions of common/ (image_write).";
    case VERDICT_MISSING:
        return "Write the image at the path raytra gets as its second argument, and hand in "
               "your folder with its Makefile at the top, as the starter has it.";
    case VERDICT_ERROR:
        if (r->hidden)
            return "Read what the program printed, below: it ended with a failure on this "
                   "scene, which is not in your starter, and wrote no image. Make sure it "
                   "reads every scene the format allows, not only the starter's.";
        return "Run the command below from the top of your folder, after make, and read what "
               "it prints: it ended with a failure and wrote no image.";
    case VERDICT_CRASHED:
        if (r->hidden)
            return "Build with `make SANITIZE=1` and run `make check`: the sanitizer names the "
                   "line that crashes. This scene is not in your starter: look for what it "
                   "may hold that the starter's scenes do not (an object, a light or a camera "
                   "placed otherwise).";
        return "Run the command below from the top of your folder after `make SANITIZE=1`: "
               "the sanitizer names the line that crashes (or run it under gdb --args).";
    case VERDICT_TIMEOUT:
        return grade_format("%s: it may take %g s here. Look for a loop that never ends, such "
                            "as rays reflected with no depth limit.",
                            r->hidden ? "Time your program on the starter's scenes (`make check`)"
                                      : "Run the command below and time it",
                            g->time_limit);
    case VERDICT_OUT_OF_MEMORY:
        return grade_format("Look for memory taken for every ray or pixel and never given "
                            "back: the program may use %s of address space here.",
                            grade_size_text(g->memory_limit));
    case VERDICT_BUILD_FAILED:
        return "Run make in a fresh copy of what you handed in and mend the first error it "
               "prints (make's last output is shown with these results).";
    default: return "";
    }
}

/* Returns the words about scene k of submission s that both formats give: the verdict and
 * its reason, the figures, the time, what to do, the command and the program's last
 * output; with `build`, make's last output too when the build failed (JUnit, whose test
 * cases stand alone). A hidden scene's words name no command that runs it: the student
 * does not have its scene file. */
char *feedback_text(const Grading *g, const Submission *s, int k, bool build)
{
    const Render *r = &g->renders[k];
    const SceneResult *res = &s->results[k];
    const char *todo = advice(g, r, res);
    bool ran = res->command != NULL;
    bool show_log = ran && verdict_info[res->verdict].tally >= TALLY_MISSING;
    /* The command that renders the scene, for a scene run or an image to make again. */
    bool command = !r->hidden &&
                   (ran || (res->verdict != VERDICT_PASS && res->verdict != VERDICT_BUILD_FAILED));
    build = build && s->build_message != NULL && s->build_log_tail != NULL;
    return grade_format(
        "%s: %s.\n%s%s%s%s%s%s%s%s%s%s", verdict_info[res->verdict].name, res->message,
        figures_text(res), res->seconds > 0 ? grade_format("Ran in %.2f s.\n", res->seconds) : "",
        todo[0] != '\0' ? grade_format("What to do: %s\n", todo) : "",
        command ? grade_format("Command (from the top of the folder): %s\n", student_command(r))
                : "",
        show_log ? "The program's last output:\n" : "",
        show_log ? (res->log_tail != NULL ? res->log_tail : "(nothing)") : "", show_log ? "\n" : "",
        build ? "The end of make's output:\n" : "", build ? s->build_log_tail : "",
        build ? "\n" : "");
}
