/* grade.h: the grader's one internal header: a class's renders, submissions and verdicts. */
#ifndef RAYTRA_GRADE_H
#define RAYTRA_GRADE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>
#include <sys/stat.h>
#include <sys/types.h>

#include "diag.h"

/* What became of one scene of one submission; docs/grading.md says what each means. */
typedef enum {
    VERDICT_PASS, VERDICT_FAIL, VERDICT_WRONG_SIZE, VERDICT_LINK, VERDICT_UNREADABLE,
    VERDICT_MISSING, VERDICT_ERROR, VERDICT_CRASHED, VERDICT_TIMEOUT, VERDICT_OUT_OF_MEMORY,
    VERDICT_BUILD_FAILED, VERDICT_COUNT
} Verdict;

/* The summary's columns, into which the verdicts fall. */
typedef enum { TALLY_PASS, TALLY_FAIL, TALLY_MISSING, TALLY_ERROR, TALLY_COUNT } Tally;

/* A verdict's name in the report and the CSV ("WRONG SIZE"), and its column. */
typedef struct {
    const char *name;
    Tally tally;
} VerdictInfo;

extern const VerdictInfo verdict_info[VERDICT_COUNT];

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
} Submission;

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
} Grading;

/* How a child ended: status is the exit status (RUN_EXITED), the signal (RUN_KILLED) or the
 * errno (RUN_NOT_RUN: fork or pipe failed); ok when it exited with status 0; output what it
 * printed, its head and tail when it printed more than the grader keeps (never NULL; it lasts
 * until the next run_program). */
typedef enum {
    RUN_EXITED, RUN_KILLED, RUN_TIMED_OUT, RUN_NOT_RUN, RUN_INTERRUPTED,
    RUN_OVER_DISK /* a student's run stopped: it wrote past its disk limit, or filled the disk */
} RunEnd;

typedef struct {
    RunEnd end;
    int status;
    double seconds;
    bool ok;
    char *output;
} RunResult;

/* What a student's build or run may reach in the sandbox (namespaces): the folders it may
 * write, the files and folders it may read, beside the toolchain; and the bytes its folders
 * may hold (0: any), past which it is stopped, with either containment. */
typedef struct {
    const char *write[4]; /* NULL-ended */
    char **read;          /* NULL-ended, or NULL */
    long long disk_limit;
} View;

/* The exit status of a child that could not exec its program (as the shell's). */
#define RUN_EXEC_FAILED 127

/* The memory limit of imgdiff, which reads students' files: none under AddressSanitizer,
 * whose shadow memory no limit leaves room for. */
#if defined(__SANITIZE_ADDRESS__)
#define RUN_OWN_MEMORY(limit) ((void)(limit), 0LL)
#else
#define RUN_OWN_MEMORY(limit) (limit)
#endif

/* The grader's exit statuses: the report written (whatever the verdicts), trouble, a stop. */
enum { EXIT_REPORTED = 0, EXIT_TROUBLE = 2, EXIT_INTERRUPTED = 130 };

/* grade_base.c */
void *grade_alloc(size_t size);
char *grade_format(const char *fmt, ...) DIAG_PRINTF(1, 2);
bool grade_fail(const char *fmt, ...) DIAG_PRINTF(1, 2);
char *grade_size_text(long long bytes);

/* grade_path.c */
int path_kind(const char *path);
bool path_make_folder(const char *path);
const char *path_fresh_folder(const char *path, FILE *notes);
char **path_list_folders(const char *folder, int *count);
bool path_same_bytes(const char *a, const char *b);
FILE *path_open_regular(const char *path, const char **kind);

/* grade_out.c */
bool out_prepare(Grading *g);

/* grade_part.c */
bool part_find_top(Grading *g);
bool part_find(Grading *g, const char *part);
bool part_render_hidden(Grading *g);
bool part_show_references(Grading *g);
void part_make_canaries(Grading *g);
double part_points(const Grading *g, const Submission *s, double *max);

/* grade_renders.c */
bool renders_read(Grading *g);
bool renders_read_hidden(Grading *g);

/* grade_conf.c */
bool conf_read(Grading *g);

/* grade_verdict.c */
void verdict_set(SceneResult *res, Verdict v, const char *fmt, ...) DIAG_PRINTF(3, 4);

/* grade_judge.c */
char *judge_image_path(const Grading *g, const Submission *s, int k);
void judge_file(const Grading *g, const Submission *s, int k, const char *path,
                const char *missing);

/* grade_build.c */
char *build_submission(const Grading *g, Submission *s);

/* grade_submission.c */
bool submission_list(Grading *g);
bool submission_grade(const Grading *g, Submission *s, FILE *f);

/* grade_user.c */
/* A user: its ids. */
typedef struct {
    uid_t uid;
    gid_t gid;
} User;

/* Seconds the keeper tries to end a student's processes before it calls them unkillable. */
#define SWEEP_GIVE_UP 30

bool user_find(const char *text, User *u);
bool user_become(User u);
int user_processes(uid_t uid, bool end);
void user_limit_processes(void);
pid_t user_sweep(User u);

/* grade_reap.c */
void contain_end_strays(const pid_t *keep, int keep_count);

/* grade_sandbox.c */
void sandbox_use(char *bwrap_path, bool closes);
char **sandbox_wrap(char *const argv[], const char *dir, const View *view, bool own_user);
char **sandbox_scene_files(const char *scene, const char *run_dir, char *also);
void sandbox_environment(const char *dir);
bool sandbox_over_disk(const View *view);

/* grade_child.c */
void child_setup(const char *dir, int out, long long memory_limit, double time_limit,
                 bool student);

/* grade_keeper.c */
/* The most students' users, one a job (--jobs takes at most 64). */
#define MAX_SLOTS 64

/* A request to the keeper, and its answer. */
enum { ASK_RUN = 1, ASK_KILL = 2, ASK_SHARE = 3 };
typedef struct {
    int ask, argc;
    long long memory_limit;
    double time_limit;
    long asker, serial; /* the asking process and its count of runs, which the answer names */
} Request;
typedef struct {
    int how; /* RUN_EXITED: status is a wait status; RUN_NOT_RUN: an errno; else not contained */
    int status;
    long asker, serial;
} Answer;

void keeper_main(const User *users, const int *sockets, int count, User grader_user,
                 pid_t grader_pid);

/* grade_contain.c */
bool contain_start(const char *run_as, const char *grader_user, int jobs);
bool contain_active(void);
int contain_users(void);
void contain_use_slot(int k);
int contain_run(char *const argv[], const char *dir, int out, long long memory_limit,
                double time_limit);
void contain_kill(void);
bool contain_answered(void);
RunEnd contain_wait(int *status);
bool contain_share(const char *path);

/* grade_run.c */
void run_init(void);
RunResult run_program(char *const argv[], const char *dir, const char *log, double time_limit,
                      long long memory_limit);
RunResult run_student(char *const argv[], const char *dir, const char *log, double time_limit,
                      long long memory_limit, const View *view);
char *run_describe(const RunResult *r);
char *run_command_line(char *const argv[], const char *dir);
char *run_quote(const char *word);
char *run_tail(const char *output);
char *run_tail_relative(const char *output, const char *work);

/* grade_containment.c */
bool containment_choose(Grading *g);

/* grade_jobs.c */
bool jobs_grade_all(Grading *g);

/* grade_results.c */
/* The first line of a results file, with the version of its format. */
#define RESULTS_MAGIC "grade-results 4"

/* A results file being read, a line at a time, split into words. */
typedef struct {
    FILE *file;
    const char *path;
    int line;
    char *text;
    size_t size;
    char *raw; /* the line as it was, before it was split */
    char *word[64];
    int count;
    bool bad; /* a word was not as expected */
} Reader;

void results_put_text(FILE *f, const char *text);
void results_put_submission(FILE *f, const Grading *g, const Submission *s);
bool results_next_line(Reader *r);
bool results_line_is(const Reader *r, const char *key, int count);
char *results_get_text(Reader *r, int k);
char *results_get_word(Reader *r, int k);
double results_get_number(Reader *r, int k);
bool results_get_submission(Reader *r, const Grading *g, Submission *s, const char *work,
                            const char *work_name);
char *results_read_submission(const Grading *g, Submission *s, const char *path);

/* grade_shard.c */
bool shard_parse(Grading *g);
void shard_select(Grading *g);
bool shard_write(const Grading *g);
bool shard_read(Grading *g, const char *folder);

/* grade_merge.c */
int merge_main(int argc, char **argv);

/* grade_utf8.c */
int utf8_read(const char *text, unsigned long *code);

/* grade_feedback.c */
char *feedback_text(const Grading *g, const Submission *s, int k, bool build);

/* grade_junit.c */
bool junit_export(const Grading *g, const char *path);

/* grade_gradescope.c */
bool gradescope_export(const Grading *g, const char *path);

/* grade_report.c */
char *report_command(const Submission *s, const SceneResult *res);
bool report_write(const Grading *g);
bool report_write_whole(const char *path, const Grading *g, void (*write)(FILE *, const Grading *));

/* grade_csv.c */
void csv_write(FILE *f, const Grading *g);

/* grade_self.c */
int self_print(const Grading *g);

#endif
