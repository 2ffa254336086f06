/* grade_run.c: a child in its own process group, under limits; how it ended, what it printed. */
#include "grade_run.h"

#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "grade_base.h"
#include "grade_cgroup.h"
#include "grade_child.h"
#include "grade_contain.h"
#include "grade_reap.h"
#include "progress.h"
#include "stop.h"
#ifdef __linux__
#include <sys/prctl.h>
#endif

/* What the grader keeps of a child's output, read through a pipe: the first and the last
 * KEEP_BYTES; what lies between is counted, never stored, and a line says how much was cut. */
#define KEEP_BYTES (64 << 10)

/* The end of a program's output that the report shows: its last lines, each cut to a
 * length. Counted in lines, so that a time printed wider in one run than in another ("in
 * 0.1 s", "in 10.2 s") does not change which lines are shown. */
#define TAIL_LINES 24
#define TAIL_LINE_BYTES 200

/* A child's output as it comes: the head, then the tail in a ring, and the count of all. */
typedef struct {
    char head[KEEP_BYTES], tail[KEEP_BYTES];
    size_t head_len;
    unsigned long long total;
} Capture;

/* SIGCHLD alone: held back by the grader, for the wait loop to wait for. */
static sigset_t sigchld;

/* Makes SIGINT, SIGTERM and SIGHUP (the terminal going away) requests to stop, which the
 * wait loop polls; holds SIGCHLD back for it to wait for; and makes the grader the parent
 * of any process a child leaves behind (a subreaper), so that it can end those too. */
void run_init(void)
{
    stop_install();
    signal(SIGHUP, stop_request);
    /* With its output piped into head, the grader must not die before ending a child. */
    signal(SIGPIPE, SIG_IGN);
    sigemptyset(&sigchld);
    sigaddset(&sigchld, SIGCHLD);
    sigprocmask(SIG_BLOCK, &sigchld, NULL);
#ifdef __linux__
    prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0);
#endif
}

/* Waits until a child ends (SIGCHLD), a signal asks to stop, or `seconds` pass. */
static void wait_for_signal(double seconds)
{
    struct timespec t = {(time_t)seconds, (long)((seconds - (double)(time_t)seconds) * 1e9)};
    sigtimedwait(&sigchld, NULL, &t);
}

/* Adds n bytes of output to the capture: to the head until it is full, then to the ring. */
static void capture_add(Capture *c, const char *bytes, size_t n)
{
    size_t to_head = c->head_len < KEEP_BYTES ? KEEP_BYTES - c->head_len : 0;
    to_head = to_head < n ? to_head : n;
    memcpy(c->head + c->head_len, bytes, to_head);
    c->head_len += to_head;
    for (size_t k = to_head; k < n;) {
        size_t at = (size_t)((c->total + k - c->head_len) % KEEP_BYTES);
        size_t run = KEEP_BYTES - at < n - k ? KEEP_BYTES - at : n - k;
        memcpy(c->tail + at, bytes + k, run);
        k += run;
    }
    c->total += n;
}

/* Reads what the pipe holds into the capture, at most 4 MiB at a time so that the limits are
 * looked at again; returns the descriptor, or -1 once it is closed at the end of the output. */
static int capture_read(Capture *c, int fd)
{
    char chunk[1 << 16];
    for (int k = 0; k < 64; k++) {
        ssize_t n = read(fd, chunk, sizeof chunk);
        if (n > 0)
            capture_add(c, chunk, (size_t)n);
        else if (n < 0 && errno == EINTR)
            continue;
        else if (n < 0 && errno == EAGAIN)
            return fd;
        else {
            close(fd);
            return -1;
        }
    }
    return fd;
}

/* Returns what the capture kept as one string: the head, a line saying how many bytes were
 * cut when some were, and the tail; a NUL byte the program printed becomes '?'. The string
 * lasts until the next call, so that a class of programs that print much takes no more
 * memory than one. */
static char *capture_text(const Capture *c)
{
    static char text[2 * KEEP_BYTES + 256];
    size_t rest = (size_t)(c->total - c->head_len); /* the bytes after the head */
    size_t tail = rest < KEEP_BYTES ? rest : KEEP_BYTES;
    unsigned long long cut = c->total - c->head_len - tail;
    char note[200] = "";
    if (cut > 0)
        snprintf(note, sizeof note,
                 "\n[grade: %llu bytes cut here: of the %llu bytes printed, "
                 "the first and the last %d KiB are kept]\n",
                 cut, c->total, KEEP_BYTES >> 10);
    size_t len = c->head_len + strlen(note) + tail;
    char *t = text;
    memcpy(t, c->head, c->head_len);
    t = stpcpy(t + c->head_len, note);
    for (size_t k = 0, from = (size_t)((c->total - tail - c->head_len) % KEEP_BYTES); k < tail; k++)
        *t++ = c->tail[(from + k) % KEEP_BYTES];
    for (size_t k = 0; k < len; k++)
        text[k] = text[k] == '\0' ? '?' : text[k];
    text[len] = '\0';
    return text;
}

/* Writes the log at path anew: the command line, the output, how the run ended. Whatever a
 * program left at the path is removed first, never followed (O_EXCL, O_NOFOLLOW). */
static void write_log(const char *path, char *const argv[], const char *dir, const RunResult *r)
{
    struct stat st;
    if (lstat(path, &st) == 0 && !S_ISDIR(st.st_mode))
        unlink(path);
    int fd = open(path, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    FILE *f = fd >= 0 ? fdopen(fd, "w") : NULL;
    if (f != NULL)
        fprintf(f, "$ %s\n%s%s[grade: %s; it ran %.2f s]\n", run_command_line(argv, dir), r->output,
                r->output[0] == '\0' || r->output[strlen(r->output) - 1] == '\n' ? "" : "\n",
                run_describe(r), r->seconds);
    if (f == NULL || fclose(f) != 0)
        fprintf(stderr, "grade: warning: cannot write the log %s: %s\n", path, strerror(errno));
    if (f == NULL && fd >= 0)
        close(fd);
}

/* Tells whether the child (pid), or the run the keeper started (pid 0), has ended. */
static bool run_ended(pid_t pid)
{
    siginfo_t info = {0};
    /* WNOWAIT leaves the child a zombie: its pid, its group's id, stays reserved. */
    return pid == 0 ? contain_answered()
                    : waitid(P_PID, (id_t)pid, &info, WEXITED | WNOHANG | WNOWAIT) != 0 ||
                          info.si_pid != 0;
}

/* Runs argv (a program found on PATH) in a child as child_setup prepares it, with at
 * most time_limit seconds and memory_limit bytes (0: no limit), killing it at the limit or
 * on a stop request; a student's (view not NULL) in the sandbox (sandbox_wrap), also
 * killed past its disk limit; then reaps it and ends everything it left behind: as the
 * student's user through the keeper when --run-as says so (grade_contain.c), else as this
 * process's child, its session killed and its strays swept. Its output comes through a
 * pipe, kept in part (Capture) and written to the log at path `log` (NULL: none). */
static RunResult run_child(char *const argv[], const char *dir, const char *log,
                           double time_limit, long long memory_limit, const View *view)
{
    bool as_student = view != NULL, kept = as_student && contain_active();
    char **run = as_student ? sandbox_wrap(argv, dir, view, kept) : (char **)argv;
    /* In namespaces, bubblewrap enters dir itself, inside. */
    const char *enter = run != argv ? NULL : dir;
    static Capture capture;
    Capture *c = &capture;
    c->head_len = 0;
    c->total = 0;
    int fds[2];
    if (pipe(fds) != 0)
        return (RunResult){.end = RUN_NOT_RUN, .status = errno, .output = ""};
    fcntl(fds[0], F_SETFD, FD_CLOEXEC);
    fcntl(fds[0], F_SETFL, O_NONBLOCK);
    double start = clock_now();
    int keeper = kept ? contain_run(run, enter, fds[1], memory_limit, time_limit) : -1;
    /* A student's run has a cgroup of its own where there may be one (the keeper makes
     * those of --run-as): its processes' memory together, and its end in one write. */
    RunCgroup group = as_student && !kept ? cgroup_run_open(memory_limit) : (RunCgroup){-1, ""};
    pid_t pid = kept ? 0 : fork();
    if (pid == 0 && !kept) {
        cgroup_enter(group);
        child_setup(enter, fds[1], memory_limit, time_limit, as_student);
        execvp(run[0], run);
        grade_fail("cannot run '%s': %s", run[0], strerror(errno));
        _exit(RUN_EXEC_FAILED);
    }
    int err = errno, fd = fds[0];
    close(fds[1]);
    if (pid < 0 || (kept && keeper < 0)) {
        cgroup_run_end(&group);
        close(fd);
        return (RunResult){.end = RUN_NOT_RUN, .status = err, .output = ""};
    }
    RunResult r = {.end = RUN_EXITED};
    double disk_looked = start;
    while (!run_ended(pid)) {
        double now = clock_now(), left = time_limit - (now - start);
        /* The disk is looked at twice a second: a folder's bytes are counted file by file. */
        bool over_disk = now - disk_looked > 0.5 && sandbox_over_disk(view);
        disk_looked = now - disk_looked > 0.5 ? now : disk_looked;
        if (stop_requested() || (time_limit > 0 && left <= 0) || over_disk) {
            r.end = stop_requested() ? RUN_INTERRUPTED
                    : over_disk      ? RUN_OVER_DISK
                                     : RUN_TIMED_OUT;
            break;
        }
        double wait = time_limit > 0 && left < 0.1 ? left : 0.1;
        /* Output wakes the loop, and so do its end (the child's exit closes the pipe) and
         * the keeper's answer; once the output has ended, SIGCHLD does. A stray SIGCHLD
         * only makes the loop look again. */
        struct pollfd p[2] = {{.fd = fd, .events = POLLIN}, {.fd = keeper, .events = POLLIN}};
        if (fd < 0 && keeper < 0)
            wait_for_signal(wait);
        else if (poll(p, 2, (int)(wait * 1000) + 1) > 0 && p[0].revents != 0)
            fd = capture_read(c, fd);
    }
    r.seconds = clock_now() - start;
    int status = 0;
    if (kept) {
        if (r.end != RUN_EXITED)
            contain_kill();
        if (contain_wait(&status) == RUN_NOT_RUN && r.end == RUN_EXITED) {
            r.end = RUN_NOT_RUN;
            r.status = status;
        }
    } else {
        /* Whatever else of the session's group still runs (a forked child of the program)
         * ends now; the child itself too, should it have been killed before its setsid. */
        kill(-pid, SIGKILL);
        kill(pid, SIGKILL);
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
            continue;
        cgroup_run_end(&group);
        reap_strays(NULL, 0);
    }
    if (r.end == RUN_EXITED && sandbox_over_disk(view))
        r.end = RUN_OVER_DISK;
    if (r.end == RUN_EXITED) {
        r.end = WIFSIGNALED(status) ? RUN_KILLED : RUN_EXITED;
        r.status = WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status);
    }
    /* bubblewrap tells a program killed by signal N by exiting with 128 + N, as a shell does
     * (and as a program that exits so): taken as the signal. */
    if (r.end == RUN_EXITED && run != argv && r.status > 128 && r.status <= 128 + 64) {
        r.end = RUN_KILLED;
        r.status -= 128;
    }
    r.ok = r.end == RUN_EXITED && r.status == 0;
    /* Everything that could write to the pipe has ended: what it holds is the last. */
    if (fd >= 0 && capture_read(c, fd) >= 0)
        close(fd);
    r.output = capture_text(c);
    if (log != NULL)
        write_log(log, argv, dir, &r);
    return r;
}

/* Runs a program of the grader's own (imgdiff, cp, sh) as run_child does. */
RunResult run_program(char *const argv[], const char *dir, const char *log, double time_limit,
                      long long memory_limit)
{
    return run_child(argv, dir, log, time_limit, memory_limit, NULL);
}

/* Runs a student's build or program as run_child does, in the sandbox with what view lets it
 * reach: with --run-as, as the student's user. */
RunResult run_student(char *const argv[], const char *dir, const char *log, double time_limit,
                      long long memory_limit, const View *view)
{
    RunResult r = run_child(argv, dir, log, time_limit, memory_limit, view);
    if (r.end != RUN_OVER_DISK)
        return r;
    /* What it wrote is removed, so that the disk is there for the rest of the class. */
    r.output = grade_format("%s", r.output);
    for (int k = 0; view->write[k] != NULL; k++) {
        char *empty[] = {"find", (char *)view->write[k], "-mindepth", "1", "-delete", NULL};
        run_child(empty, NULL, NULL, 600, 0, &(View){{view->write[k], NULL}, NULL, 0});
    }
    return r;
}

/* Returns how a run ended: "exit status 2", "killed by signal 11 (Segmentation fault)". */
char *run_describe(const RunResult *r)
{
    switch (r->end) {
    case RUN_EXITED: return grade_format("exit status %d", r->status);
    case RUN_KILLED:
        return grade_format("killed by signal %d (%s)", r->status, strsignal(r->status));
    case RUN_TIMED_OUT: return grade_format("still running after %.0f s", r->seconds);
    case RUN_NOT_RUN: return grade_format("not started: %s", strerror(r->status));
    case RUN_OVER_DISK:
        return "stopped: it wrote more than its disk limit (--disk-limit), or filled the disk";
    default: return "interrupted";
    }
}

/* Returns word as the shell reads it: as it is when it holds only safe characters, else in
 * single quotes, each of its own written '\''. */
char *run_quote(const char *word)
{
    if (word[0] != '\0' && strspn(word, "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                        "0123456789_-./=:,+@%") == strlen(word))
        return grade_format("%s", word);
    char *out = grade_alloc(4 * strlen(word) + 3), *o = out;
    *o++ = '\'';
    for (const char *w = word; *w != '\0'; w++) {
        if (*w == '\'')
            o = stpcpy(o, "'\\''");
        else
            *o++ = *w;
    }
    strcpy(o, "'");
    return out;
}

/* Returns the command line of a run as a shell would take it: "cd DIR && PROGRAM ARGS",
 * every word quoted as it needs, so that it can be pasted to run the same again. */
char *run_command_line(char *const argv[], const char *dir)
{
    char *line = dir != NULL ? grade_format("cd %s &&", run_quote(dir)) : "";
    for (char *const *a = argv; *a != NULL; a++)
        line = grade_format("%s%s%s", line, line[0] != '\0' ? " " : "", run_quote(*a));
    return line;
}

/* Returns the last TAIL_LINES lines of a program's output, each cut to TAIL_LINE_BYTES,
 * "[...]" for what was cut; NULL when it printed nothing but blanks. */
char *run_tail(const char *output)
{
    size_t n = strlen(output);
    while (n > 0 && isspace((unsigned char)output[n - 1]))
        n--;
    /* Back to just after the TAIL_LINES-th line break from the end, or to the start. */
    size_t from = n;
    for (int lines = 0; from > 0 && (output[from - 1] != '\n' || ++lines < TAIL_LINES);)
        from--;
    char *text = grade_alloc(n - from + 6 * TAIL_LINES + 8), *t = text;
    if (from > 0)
        t = stpcpy(t, "[...]\n");
    for (const char *line = output + from, *end = output + n; line < end;) {
        size_t len = strcspn(line, "\n");
        len = len < (size_t)(end - line) ? len : (size_t)(end - line);
        memcpy(t, line, len < TAIL_LINE_BYTES ? len : TAIL_LINE_BYTES);
        t += len < TAIL_LINE_BYTES ? len : TAIL_LINE_BYTES;
        t = stpcpy(t, len > TAIL_LINE_BYTES ? "[...]" : "");
        line += len;
        if (line < end)
            *t++ = *line++;
    }
    *t = '\0';
    return n > 0 ? text : NULL;
}

/* Returns the end of a program's output (run_tail) with the path of the work folder `work`
 * written "work" (as in a compiler's -I flags, or a program naming its folder), so that
 * what the report shows does not depend on where the work folder is: a shard's, merged. */
char *run_tail_relative(const char *output, const char *work)
{
    size_t len = strlen(work);
    char *text = grade_alloc(strlen(output) + 1), *t = text;
    for (const char *p = output; *p != '\0';)
        if (strncmp(p, work, len) == 0)
            t = stpcpy(t, "work"), p += len;
        else
            *t++ = *p++;
    return run_tail(text);
}
