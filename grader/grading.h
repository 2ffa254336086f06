/* grading.h: what a grading run knows (renders, submissions, verdicts), and how a child it ran ended. */
#ifndef RAYTRA_GRADING_H
#define RAYTRA_GRADING_H

#include <stdbool.h>
#include <stdio.h>

/* What became of one scene of one submission; docs/grading.md says what each means. */
typedef enum {
    VERDICT_PASS, VERDICT_FAIL, VERDICT_WRONG_SIZE, VERDICT_LINK, VERDICT_UNREADABLE,
    VERDICT_MISSING, VERDICT_ERROR, VERDICT_CRASHED, VERDICT_TIMEOUT, VERDICT_OUT_OF_MEMORY,
    VERDICT_BUILD_FAILED, VERDICT_COUNT
} Verdict;

/* The summary's columns, into which the verdicts fall. */
typedef enum { TALLY_PASS, TALLY_FAIL, TALLY_MISSING, TALLY_ERROR, TALLY_COUNT } Tally;

/* imgdiff's figures for an image against its reference: its --machine lines. */
typedef struct {
    double threshold, allow; /* the tolerances imgdiff used */
    double max[3];           /* the largest difference in R, G and B, from 0 to 1 */
    double mean, rmse, psnr; /* psnr in dB; infinite for equal images */
    long differing, pixels;  /* differing: pixels with a channel difference above threshold */
    int box[4];        /* x0, y0, x1, y1 around the differing pixels (when some differ) */
    double heat_scale; /* the difference the heat map shows white */
    /* A Monte Carlo render's statistical test (docs/grading.md): the largest |z| of the
     * bias test and its critical value; the noise ratio and its bounds; the pixels the
     * references saw without noise that differ. */
    double bias_z, bias_critical, noise, noise_low, noise_high;
    long exact;
} Figures;

/* Where a render's positional words begin in its argv, after program, scene and image. */
#define RENDER_WORDS 3

/* How a render's image is judged (renders.txt; docs/grading.md): against its reference within
 * the tolerances; pixel for pixel against the program's own image of an earlier render
 * (IMAGE=OTHER); or by coverage, drawn wherever a reference is drawn (IMAGE>MASK). */
typedef enum { JUDGE_REFERENCE, JUDGE_SAME_AS, JUDGE_COVER } Judge;

/* One line of renders.txt: a reference image and the scene it was rendered from. */
typedef struct {
    char *image;          /* the reference's file name: spheres-three.png */
    char *name;           /* the same without the extension: the scene's name in the report */
    char *scene;          /* the scene file as renders.txt gives it, from the repository's top */
    char **argv;          /* a student's command line: the program, the scene's path and the
                           * output image (the program and the image set for each run), then
                           * from argv[RENDER_WORDS] on the positional words, NULL-ended */
    char *reference;      /* the reference image's path */
    char *reference_show; /* its thumbnail for the report */
    char **model;         /* a hidden scene's reference: the model answer's command line, every
                           * word of renders.txt (the program and image set when it runs) */
    double points;        /* what passing it is worth (grading.conf; 1 by default) */
    const char *visibility; /* Gradescope's: visible, hidden, after_due_date, after_published */
    bool hidden;          /* an instructor's own scene (--hidden), shipped in no starter */
    bool statistical;     /* a Monte Carlo render (~IMAGE), judged by its statistics */
    char *shipped;        /* the image the references folder ships for it: its reference, or
                           * beside a Monte Carlo render's statistics raytra's own render;
                           * NULL for a hidden scene */
    char *canary;         /* the reference's bytes marked as the grader's (a PNG with a text
                           * chunk more): what a program that copies the file it found in its
                           * own folder writes; NULL for a reference that is no PNG */
    Judge judge;
    int same_as; /* JUDGE_SAME_AS: the earlier render whose image this one must equal */
    char *mask;  /* JUDGE_COVER: the reference whose drawn pixels the image must cover */
    char *why;   /* what a failure of JUDGE_SAME_AS or JUDGE_COVER means (#? line), or NULL */
} Render;

/* The grading of one scene of one submission. */
typedef struct {
    Verdict verdict;
    char message[512]; /* the verdict's reason, in a sentence */
    bool compared;     /* figures holds imgdiff's answer */
    bool identical;    /* equal to the reference: its thumbnail and a black map serve */
    Figures figures;
    char *image_show, *heat_show; /* where imgdiff put the thumbnails, or NULL */
    char *log_tail;               /* the last lines the program printed, or NULL */
    char *command; /* the command line run in the submission's run folder, or NULL */
    bool copy; /* the file is byte for byte the reference's: flagged for the instructor */
    double relative_width; /* a wrong-sized image's width over the reference's; else 0 */
    double seconds;        /* how long the program ran; 0 when none was run */
} SceneResult;

/* One student's submission: a folder of images, or of sources whose make builds raytra. */
typedef struct {
    char *name;           /* the folder's name, as it is (it may hold any character) */
    char *path;           /* the folder */
    char *work;           /* its work folder, named safely: OUT/work/03-alice */
    bool program;         /* it has a Makefile: built and run rather than read */
    char *link;           /* the folder is a symbolic link to this: not graded; or NULL */
    char *build_message;  /* why the build failed; NULL when it did not */
    char *build_log_tail; /* the end of make's output, or NULL */
    char *removed;        /* the build outputs it carried, removed before make, or NULL */
    SceneResult *results; /* one a render */
    int tally[TALLY_COUNT];
    double submitted;        /* when it was handed in, in seconds since 1970, if time_source */
    const char *time_source; /* where that time comes from: "git" (its last commit), "files"
                              * (its newest file), "given" (--submitted-at); NULL: not known */
} Submission;

/* When work is due and what lateness costs (grading.conf's due, grace, penalty_per_day,
 * max_penalty, max_late_days and late_until; --due and --late-until): zero means none. */
typedef struct {
    bool due_set;      /* a due date is given: lateness is counted */
    double due;        /* the due date, in seconds since 1970 */
    int zone;          /* its time zone, minutes east of UTC: the report's times are in it */
    double grace;      /* seconds after the due date that are not late */
    double per_day;    /* the penalty for each day late (rounded up), percent of the points */
    bool cap_set;      /* the penalty stops at cap, percent */
    double cap;
    bool max_days_set; /* more days late than max_days: the work gets 0 */
    int max_days;
    bool until_set;    /* handed in after until: the work gets 0 */
    double until;
} LatePolicy;

/* Everything a grading run knows: what was asked, what was found, what came out. */
typedef struct {
    char *top;        /* the repository's top folder */
    const char *part; /* the part's folder name: 1.1-spheres-red */
    char *references; /* its references folder */
    Render *renders;
    int render_count;
    char *illustrations; /* the names of the renders marked '!', not graded; or NULL */
    Submission *subs;
    int sub_count;
    const char *submissions; /* the submissions folder, as given */
    const char *out;         /* where report.html and grades.csv go */
    char *work;              /* OUT/work: copies, builds, images, logs, heat maps */
    char *imgdiff;           /* the imgdiff program */
    const char *threshold;   /* imgdiff's --threshold, as text */
    const char *allow;       /* imgdiff's --allow, as text */
    const char *standard;    /* imgdiff's --standard: good or ok */
    double time_limit;       /* seconds for each run of a student's program */
    double build_time_limit; /* seconds for make */
    long long memory_limit;  /* bytes of address space; 0: none */
    long long disk_limit;    /* bytes a submission's folders may hold; 0: no limit */
    const char *run_as;      /* --run-as: students' users, one a job (as root); or NULL */
    const char *grader_user; /* --grader-user: the user the grader becomes with --run-as */
    const char *sandbox;     /* --sandbox as given (auto, namespaces, fallback); once grading
                              * has begun, the containment in force in words (sandbox_name) */
    bool quiet, self, help;  /* self: submissions is one student's folder */
    int jobs;                /* submissions graded at a time (--jobs) */
    const char *shard;       /* --shard K/N as given, or NULL */
    int shard_k, shard_n;    /* this run grades the k-th of n slices (1 <= k <= n); n 0: all */
    const char *junit;       /* --junit: a JUnit XML file to write too, or NULL */
    const char *gradescope;  /* --gradescope: Gradescope's results.json to write too, or NULL */
    const char *hidden;      /* --hidden: the folder of the instructor's own scenes, or NULL */
    const char *conf;        /* --grading-conf: points and visibility; NULL: the part's */
    double part_points;      /* what the whole part is worth (grading.conf); 0: the sum */
    char **members;          /* the names of the whole class, of which subs may be a slice */
    int member_count;
    char *heading;           /* a shard read back: what merge checks to be the same in all */
    bool merging;            /* grade merge: no class is read, no program run */
    FILE *progress;          /* where progress lines and notes go: stderr, or with quiet none */
    char started[32];        /* when grading began, for the report */
    double began;            /* when grading began, from clock_now: results.json's time */
    const char *only;        /* --only NAME[,NAME...]: the students regraded into the grading
                              * of the class in OUT, the others' results kept; or NULL */
    LatePolicy late;         /* when work is due, and what lateness costs */
    const char *due_given;   /* --due: the due date, in place of grading.conf's; or NULL */
    const char *until_given; /* --late-until: the end of late work, in place of grading.conf's */
    const char *submitted_at; /* --submitted-at: when the one submission of --self was handed
                               * in (Gradescope's time), in place of its files'; or NULL */
} Grading;


#endif
