/* grade.h: what tools/grade knows of a class: the part's renders, the submissions, the verdicts. */
#ifndef RAYTRA_GRADE_H
#define RAYTRA_GRADE_H

#include <stdbool.h>
#include <stddef.h>

#include "diag.h"

/* What became of one scene of one submission. */
typedef enum {
    VERDICT_PASS,          /* matches the reference within the tolerances */
    VERDICT_FAIL,          /* differs from it */
    VERDICT_WRONG_SIZE,    /* has another width or height */
    VERDICT_LINK,          /* is a symbolic link, or a hard link to the reference */
    VERDICT_UNREADABLE,    /* is not a regular file holding an image imgdiff can read */
    VERDICT_MISSING,       /* there is no image */
    VERDICT_ERROR,         /* the program exited with a failure status and wrote no image */
    VERDICT_CRASHED,       /* the program was killed by a signal */
    VERDICT_TIMEOUT,       /* the program did not finish within the time limit */
    VERDICT_OUT_OF_MEMORY, /* the program said it ran out of memory, or the system killed it */
    VERDICT_BUILD_FAILED,  /* make failed, so there was no program to run */
    VERDICT_COUNT
} Verdict;

/* The summary's columns, into which the verdicts fall. */
typedef enum { TALLY_PASS, TALLY_FAIL, TALLY_MISSING, TALLY_ERROR, TALLY_COUNT } Tally;

/* What the report and the CSV call a verdict ("WRONG SIZE"), the summary column it counts
 * in (a wrong, linked or unreadable image is a failed one; a program that made none, an
 * error), and what it means, for the report's legend. */
typedef struct {
    const char *name;
    Tally tally;
    const char *meaning;
} VerdictInfo;

extern const VerdictInfo verdict_info[VERDICT_COUNT];

/* imgdiff's figures for an image against its reference (imgdiff --machine). */
typedef struct {
    double threshold, allow; /* the tolerances imgdiff used */
    double max[3];           /* the largest difference in R, G and B, from 0 to 1 */
    double mean, rmse;       /* over every channel of every pixel */
    double psnr;             /* in dB; infinite for equal images */
    long differing;          /* pixels with a channel difference above the threshold */
    long pixels;
    bool has_box;
    int box[4];        /* x0, y0, x1, y1 around the differing pixels, y from the top */
    double heat_scale; /* the difference the heat map shows white; 0: no heat map */
} Figures;

/* One line of renders.txt: a reference image and the scene it was rendered from. */
typedef struct {
    char *image;          /* the reference's file name: spheres-three.png */
    char *name;           /* the same without the extension: the scene's name in the report */
    char *scene;          /* the scene file as renders.txt gives it, from the repository's top */
    char *scene_path;     /* the scene file's absolute path, given to students' programs */
    char **args;          /* the positional extra words for students' programs, NULL-ended */
    char *reference;      /* the reference image's path */
    char *reference_show; /* its thumbnail (PNG) for the report */
} Render;

/* The grading of one scene of one submission. */
typedef struct {
    Verdict verdict;
    char message[512]; /* the verdict's reason, in a sentence */
    bool compared;     /* figures holds imgdiff's answer */
    bool identical;    /* equal to the reference: its thumbnail and a black map serve */
    Figures figures;
    char *image_show;      /* the thumbnail of the submitted image, or NULL */
    char *heat_show;       /* the thumbnail of the heat map, or NULL */
    char *log_tail;        /* the last lines the program printed, or NULL */
    double relative_width; /* a wrong-sized image's width over the reference's; else 0 */
    double seconds;        /* how long the program ran; below 0 when none was run */
} SceneResult;

/* One student's submission: a folder of images, or of sources whose make builds raytra. */
typedef struct {
    char *name;              /* the folder's name, as it is (it may hold any character) */
    char *path;              /* the folder */
    char *work;              /* its work folder, named safely: OUT/work/03-alice */
    bool program;            /* it has a Makefile: built and run rather than read */
    char *link;              /* the folder is a symbolic link to this: not graded; or NULL */
    char build_message[512]; /* why the build failed; empty when it did not */
    char *build_log_tail;    /* the end of make's output, or NULL */
    SceneResult *results;    /* one a render */
    int tally[TALLY_COUNT];
    int verdicts[VERDICT_COUNT];
} Submission;

/* Everything a grading run knows: what was asked, what was found, what came out. */
typedef struct {
    const char *part; /* the part's folder name: 1.1-spheres-red */
    char *references; /* its references folder */
    Render *renders;
    int render_count;
    char *illustrations; /* the names of the renders marked '!', not graded; or NULL */
    Submission *subs;
    int sub_count;
    const char *submissions; /* the submissions folder, as given */
    char *out;               /* where report.html and grades.csv go */
    char *work;              /* OUT/work: copies, builds, images, logs, heat maps */
    char *imgdiff;           /* the imgdiff program */
    const char *threshold;   /* imgdiff's --threshold, as text */
    const char *allow;       /* imgdiff's --allow, as text */
    double time_limit;       /* seconds for each run of a student's program */
    double build_time_limit; /* seconds for make */
    long long memory_limit;  /* bytes of address space; 0: none */
    bool quiet;              /* no progress lines */
    bool self;               /* submissions is one student's folder: a check before handing in */
    char started[32];        /* when grading began, for the report */
} Grading;

void *grade_alloc(size_t size);
char *grade_format(const char *fmt, ...) DIAG_PRINTF(1, 2);
char *grade_copy(const char *text);
void grade_size_text(long long bytes, char *text, size_t size);
bool grade_is_folder(const char *path);
bool grade_is_file(const char *path);
bool grade_make_folder(const char *path, bool anew);
void grade_print_first_line(const char *prefix, const char *path);
void grade_verdict(SceneResult *res, Verdict v, const char *fmt, ...) DIAG_PRINTF(3, 4);

#endif
