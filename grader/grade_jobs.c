/* grade_jobs.c: grading the submissions N at a time, each in a worker process of its own. */
#include "grade_jobs.h"

#include <errno.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

#include "contain.h"
#include "grade_base.h"
#include "grade_eta.h"
#include "grade_results.h"
#include "grade_submission.h"
#include "grade_verdict.h"
#include "outfile.h"
#include "progress.h"
#include "reap.h"
#include "stop.h"

/* Exit statuses of a worker: its results written, or a stop asked for. */
enum { WORKER_DONE = 0, WORKER_STOPPED = 3, WORKER_TROUBLE = 4 };

/* Returns the file through which worker k hands its submission's results to the grader. */
static char *results_path(const Grading *g, int k)
{
    return grade_format("%s/.results-%d", g->work, k + 1);
}

/* In a new worker: grades submission k with its progress kept, its students' programs run
 * as the user of job `slot` (--run-as), and writes both to results_path (whole or not at
 * all); never returns. */
static void work(Grading *g, int k, int slot)
{
    contain_use_slot(slot);
#ifdef __linux__
    /* Orphans of the submission's programs come to the worker, which ends them; the worker
     * ends should the grader die. */
    prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0);
    prctl(PR_SET_PDEATHSIG, SIGTERM, 0, 0, 0);
#endif
    char *told = NULL;
    size_t size = 0;
    FILE *progress = open_memstream(&told, &size);
    if (progress == NULL || !submission_grade(g, &g->subs[k], progress))
        _exit(stop_requested() ? WORKER_STOPPED : WORKER_TROUBLE);
    fclose(progress);
    OutFile out;
    Error err;
    char *path = results_path(g, k);
    if (!outfile_open(&out, path, &err))
        _exit(WORKER_TROUBLE);
    results_put_submission(out.file, g, &g->subs[k]);
    fputs("told", out.file);
    /* The worker's told text goes through the same escaping as the results. */
    results_put_text(out.file, told);
    fputc('\n', out.file);
    _exit(outfile_commit(&out, &err) ? WORKER_DONE : WORKER_TROUBLE);
}

/* Takes in what worker k handed over, and tells its progress, the line ended with `end`
 * (how far the class is); a worker that ended without its results gets every scene an
 * ERROR saying so. */
static void collect(Grading *g, int k, int status, const char *end)
{
    Submission *s = &g->subs[k];
    char *path = results_path(g, k);
    char *told = WIFEXITED(status) && WEXITSTATUS(status) == WORKER_DONE
                     ? results_read_submission(g, s, path)
                     : NULL;
    unlink(path);
    if (told != NULL) {
        fprintf(g->progress, "%s%s\n", told, end);
        return;
    }
    if (stop_requested())
        return;
    char *why = WIFSIGNALED(status) ? grade_format("it was killed by signal %d", WTERMSIG(status))
                : WEXITSTATUS(status) == WORKER_DONE
                    ? "what it wrote could not be read"
                    : grade_format("its exit status was %d", WEXITSTATUS(status));
    fprintf(g->progress, "grading %s: the grader's worker ended without its results (%s)%s\n",
            s->name, why, end);
    s->results = grade_alloc((size_t)g->render_count * sizeof *s->results);
    memset(s->tally, 0, sizeof s->tally);
    for (int r = 0; r < g->render_count; r++) {
        s->results[r].verdict = VERDICT_ERROR;
        snprintf(s->results[r].message, sizeof s->results[r].message,
                 "the grader's worker for this submission ended without its results (%s)", why);
        s->tally[verdict_info[VERDICT_ERROR].tally]++;
    }
}

/* Grades the submissions in worker processes, g->jobs at a time; each worker forks from the
 * grader with all it knows, and hands its results back through a file; `eta` counts them
 * done. False when interrupted. */
static bool grade_in_workers(Grading *g, Eta *eta)
{
    pid_t *pid = grade_alloc((size_t)g->sub_count * sizeof *pid);
    pid_t *live = grade_alloc((size_t)g->jobs * sizeof *live); /* the workers, by job */
    int *job = grade_alloc((size_t)g->sub_count * sizeof *job);
    double *began = grade_alloc((size_t)g->sub_count * sizeof *began);
    double *running = grade_alloc((size_t)g->jobs * sizeof *running);
    int next = 0, running_count = 0;
    bool told_stop = false;
    while (next < g->sub_count || running_count > 0) {
        for (; running_count < g->jobs && next < g->sub_count && !stop_requested();
             next++, running_count++) {
            fflush(NULL);
            began[next] = clock_now();
            for (job[next] = 0; live[job[next]] != 0;)
                job[next]++;
            if ((pid[next] = fork()) == 0)
                work(g, next, job[next]);
            if (pid[next] < 0)
                return grade_fail("cannot start a worker: %s", strerror(errno));
            live[job[next]] = pid[next];
        }
        int status, k = 0;
        pid_t ended = waitpid(-1, &status, 0);
        if (ended < 0 && errno != EINTR)
            break;
        /* A stop asked of the grader alone (kill PID) is passed on to its workers. */
        if (stop_requested() && !told_stop) {
            told_stop = true;
            for (int w = 0; w < next; w++)
                if (pid[w] > 0)
                    kill(pid[w], SIGTERM);
        }
        while (ended > 0 && k < next && pid[k] != ended)
            k++;
        if (ended <= 0 || k == next) /* interrupted, or an orphan the grader adopted */
            continue;
        pid[k] = 0;
        live[job[k]] = 0;
        running_count--;
        /* What the worker's programs left (a worker killed by one) came to the grader: it
         * ends now, the other workers and theirs kept. */
        reap_strays(live, g->jobs);
        /* How far the class is: the ETA counts what the workers still running have done. */
        int n = 0;
        for (int w = 0; w < next; w++)
            if (pid[w] > 0)
                running[n++] = began[w];
        collect(g, k, status, eta_done(eta, clock_now() - began[k], running, n));
    }
    reap_strays(NULL, 0);
    return !stop_requested();
}

/* Grades every submission of g (a shard's slice with --shard, those named with --only),
 * --jobs at a time, telling the progress on g->progress, a line a submission that ends with
 * how many are done, the time elapsed and an ETA; false when interrupted. */
bool jobs_grade_all(Grading *g)
{
    FILE *f = g->progress;
    fprintf(f, "grade: part %s, %d scene%s, %d submission%s", g->part, g->render_count,
            g->render_count == 1 ? "" : "s", g->sub_count, g->sub_count == 1 ? "" : "s");
    if (g->shard_n > 0)
        fprintf(f, " (shard %d of %d of a class of %d)", g->shard_k, g->shard_n, g->member_count);
    if (g->only != NULL)
        fprintf(f, " (regraded with --only, of a class of %d)", g->member_count);
    fprintf(f, g->jobs > 1 ? ", %d at a time\n" : "\n", g->jobs);
    fprintf(f, "grade: sandbox: %s\n", g->sandbox);
    if (g->illustrations != NULL)
        fprintf(f, "grade: not graded (illustrations): %s\n", g->illustrations);
    Eta eta;
    eta_start(&eta, g->sub_count, g->jobs);
    if (g->jobs > 1 && g->sub_count > 1)
        return grade_in_workers(g, &eta);
    for (int k = 0; k < g->sub_count; k++) {
        double began = clock_now();
        if (!submission_grade(g, &g->subs[k], f))
            return false;
        /* --self's one submission needs no count. */
        fprintf(f, "%s\n", g->self ? "" : eta_done(&eta, clock_now() - began, NULL, 0));
    }
    return true;
}
