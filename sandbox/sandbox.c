/* sandbox.c: a student's build or run in namespaces of its own (bubblewrap), or the fallback's walls; the sandbox's messages. */
#define _GNU_SOURCE /* environ */
#include "sandbox.h"

#include <ftw.h>
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

/* The program whose messages the sandbox's are: "NAME: what went wrong". */
static const char *teller = "sandbox";

/* The containment in force: namespaces (bubblewrap found and working) or the fallback. */
static bool namespaces;
static char *bwrap;          /* bubblewrap's path, when namespaces */
static bool closes_userns; /* it has --disable-userns (bubblewrap 0.8, Debian 12; not 11) */

/* What every sandbox holds read-only: the toolchain and the few files of /etc it reads. A
 * top-level folder that is a link (/lib on a merged /usr) is made the same link. */
static const char *const toolchain[] = {"/usr", "/bin", "/sbin", "/lib", "/lib32", "/lib64",
                                        "/libx32", "/etc/alternatives", "/etc/ld.so.cache",
                                        "/etc/ld.so.conf", "/etc/ld.so.conf.d", "/etc/passwd",
                                        "/etc/group", "/etc/localtime"};

/* The free space below which a student's run is stopped, so that the report can be written. */
#define DISK_RESERVE (256LL << 20)

/* Makes the sandbox's messages of trouble the program's: "program: what went wrong". */
void sandbox_tell_as(const char *program)
{
    teller = program;
}

/* Returns the name of the program whose messages the sandbox's are. */
const char *sandbox_teller(void)
{
    return teller;
}

/* Prints the program's name and a message made as printf makes it; returns false, to end a
 * chain. */
bool sandbox_fail(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "%s: ", teller);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    return false;
}

/* Puts students' builds and runs in namespaces of bubblewrap, the program at bwrap_path
 * (closes: it has --disable-userns), or with NULL in the fallback's walls. */
void sandbox_use(char *bwrap_path, bool closes)
{
    bwrap = bwrap_path;
    closes_userns = closes;
    namespaces = bwrap_path != NULL;
}

/* Tells whether students' builds and runs are in bubblewrap's namespaces. */
bool sandbox_namespaces(void)
{
    return namespaces;
}

/* Returns argv, run in folder dir (NULL: /), as the sandbox runs it: inside bubblewrap,
 * which sees view's folders writable, its reads read-only, the toolchain read-only, and
 * nothing else, without capabilities, and as a user of its own when own_user (--run-as);
 * with the fallback, argv itself. What it returns otherwise is the caller's to free. */
char **sandbox_wrap(char *const argv[], const char *dir, const SandboxView *view, bool own_user)
{
    if (!namespaces)
        return (char **)argv;
    static char *const opening[] = {
        "--unshare-user", "--unshare-ipc", "--unshare-pid", "--unshare-net", "--unshare-uts",
        "--unshare-cgroup-try", "--die-with-parent", "--new-session",
        "--hostname", "raytra", "--cap-drop", "ALL", "--proc", "/proc", "--dev", "/dev",
        "--tmpfs", "/tmp", NULL};
    size_t n = 0, room = 64 + 3 * (sizeof toolchain / sizeof *toolchain);
    for (char **r = view->read; r != NULL && *r != NULL; r++)
        room += 3;
    for (char *const *a = argv; *a != NULL; a++)
        room++;
    /* The targets of the toolchain's links, read once. */
    static char targets[sizeof toolchain / sizeof *toolchain][PATH_MAX];
    char **w = malloc(room * sizeof *w);
    if (w == NULL)
        return NULL;
    w[n++] = bwrap;
    for (char *const *o = opening; *o != NULL; o++)
        w[n++] = *o;
    if (closes_userns)
        w[n++] = "--disable-userns";
    /* Root's uid, kept outside the namespace, is not shown inside: the program is nobody. */
    if (geteuid() == 0 && !own_user) {
        static char *const nobody[] = {"--uid", "65534", "--gid", "65534", NULL};
        for (char *const *o = nobody; *o != NULL; o++)
            w[n++] = *o;
    }
    for (size_t k = 0; k < sizeof toolchain / sizeof *toolchain; k++) {
        const char *p = toolchain[k];
        if (targets[k][0] == '\0' && strchr(p + 1, '/') == NULL &&
            readlink(p, targets[k], sizeof targets[k] - 1) <= 0)
            targets[k][0] = '\0';
        w[n++] = targets[k][0] != '\0' ? "--symlink" : "--ro-bind-try";
        w[n++] = targets[k][0] != '\0' ? targets[k] : (char *)p;
        w[n++] = (char *)p;
    }
    for (char **r = view->read; r != NULL && *r != NULL; r++) {
        w[n++] = "--ro-bind";
        w[n++] = *r;
        w[n++] = *r;
    }
    for (int k = 0; view->write[k] != NULL; k++) {
        w[n++] = "--bind";
        w[n++] = (char *)view->write[k];
        w[n++] = (char *)view->write[k];
    }
    w[n++] = "--chdir";
    w[n++] = (char *)(dir != NULL ? dir : "/");
    w[n++] = "--";
    for (char *const *a = argv; *a != NULL; a++)
        w[n++] = *a;
    w[n] = NULL;
    return w;
}

/* Makes the environment of this process, about to exec a student's build or run in dir,
 * the sandbox's: a fixed PATH, locale and home, nothing of the grader's (tokens, HOME). */
void sandbox_environment(const char *dir)
{
    static char home[PATH_MAX + 8], tmpdir[PATH_MAX + 8];
    static char *env[] = {"PATH=/usr/local/bin:/usr/bin:/bin", "LANG=C.UTF-8", "TERM=dumb",
                          home, tmpdir, NULL};
    snprintf(home, sizeof home, "HOME=%s", dir != NULL ? dir : "/tmp");
    snprintf(tmpdir, sizeof tmpdir, "TMPDIR=%s", namespaces || dir == NULL ? "/tmp" : dir);
    environ = env;
}

/* The bytes and files counted so far by count_bytes (nftw's visits take no argument). */
static long long counted_bytes, counted_files;

/* nftw's visit: adds what a file holds on the disk to counted_bytes; stops past a million. */
static int count_bytes(const char *path, const struct stat *st, int type, struct FTW *ftw)
{
    (void)path, (void)type, (void)ftw;
    counted_bytes += (long long)st->st_blocks * 512;
    return ++counted_files > 1000000;
}

/* Tells whether a student's build or run has written more than view's disk limit into its
 * folders (a million files count as more), or left the disk less than DISK_RESERVE free. */
bool sandbox_over_disk(const SandboxView *view)
{
    struct statvfs fs;
    if (view == NULL || view->write[0] == NULL || view->disk_limit <= 0)
        return false;
    if (statvfs(view->write[0], &fs) == 0 &&
        (long long)fs.f_bavail * (long long)fs.f_frsize < DISK_RESERVE)
        return true;
    counted_bytes = counted_files = 0;
    for (int k = 0; view->write[k] != NULL; k++)
        if (nftw(view->write[k], count_bytes, 16, FTW_PHYS) > 0)
            return true;
    return counted_bytes > view->disk_limit;
}
