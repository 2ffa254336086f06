/* grade_sandbox.c: a student's build or run in namespaces of its own (bubblewrap), or the fallback's walls. */
#define _GNU_SOURCE /* environ */
#include "grade_sandbox.h"

#include <errno.h>
#include <ftw.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include "grade_base.h"
#include "grade_path.h"

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

/* Puts students' builds and runs in namespaces of bubblewrap, the program at bwrap_path
 * (closes: it has --disable-userns), or with NULL in the fallback's walls. */
void sandbox_use(char *bwrap_path, bool closes)
{
    bwrap = bwrap_path;
    closes_userns = closes;
    namespaces = bwrap_path != NULL;
}

/* Returns argv, run in folder dir (NULL: /), as the sandbox runs it: inside bubblewrap,
 * which sees view's folders writable, its reads read-only, the toolchain read-only, and
 * nothing else, without capabilities, and as a user of its own when own_user (--run-as);
 * with the fallback, argv itself. */
char **sandbox_wrap(char *const argv[], const char *dir, const View *view, bool own_user)
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
    char **w = grade_alloc(room * sizeof *w);
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
        char target[4096];
        ssize_t len = strchr(p + 1, '/') == NULL ? readlink(p, target, sizeof target - 1) : -1;
        w[n++] = len > 0 ? "--symlink" : "--ro-bind-try";
        w[n++] = len > 0 ? grade_format("%.*s", (int)len, target) : (char *)p;
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
bool sandbox_over_disk(const View *view)
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

/* Returns the real path of the regular file at path, or NULL. */
static char *real_file(const char *path)
{
    char real[PATH_MAX];
    return realpath(path, real) != NULL && path_kind(real) == S_IFREG
               ? grade_format("%s", real)
               : NULL;
}

/* Returns what a render of the scene at `scene` (from the folder run_dir) reads, which its
 * sandbox shows read-only, NULL-ended: `also` (the program's folder), the scene, and each
 * mesh it names on a `w` line, found as raytra finds it (docs/scene-format.md): beside the
 * scene, in each folder above, then in run_dir. A mesh found nowhere is left out: raytra
 * then says it is missing. */
char **sandbox_scene_files(const char *scene, const char *run_dir, char *also)
{
    const char *at = scene[0] == '/' ? scene : grade_format("%s/%s", run_dir, scene);
    char *real = real_file(at);
    size_t n = 0, room = 8;
    char **files = grade_alloc(room * sizeof *files);
    files[n++] = also;
    if (real == NULL)
        return files;
    files[n++] = real;
    FILE *f = fopen(real, "r");
    char line[4096];
    while (f != NULL && fgets(line, sizeof line, f) != NULL) {
        char *p = line + strspn(line, " \t");
        if (p[0] != 'w' || (p[1] != ' ' && p[1] != '\t'))
            continue;
        p += 1 + strspn(p + 1, " \t");
        p[strcspn(p, "\r\n")] = '\0';
        for (size_t end = strlen(p); end > 0 && (p[end - 1] == ' ' || p[end - 1] == '\t');)
            p[--end] = '\0';
        char *dir = grade_format("%s", real), *found = p[0] == '/' ? real_file(p) : NULL;
        for (char *slash; p[0] != '/' && found == NULL && (slash = strrchr(dir, '/')) != NULL;) {
            *slash = '\0';
            found = real_file(grade_format("%s/%s", dir, p));
        }
        if (found == NULL && p[0] != '/')
            found = real_file(grade_format("%s/%s", run_dir, p));
        if (found != NULL && n + 2 > room) {
            char **grown = grade_alloc((room *= 2) * sizeof *grown);
            memcpy(grown, files, n * sizeof *files);
            files = grown;
        }
        if (found != NULL)
            files[n++] = found;
    }
    if (f != NULL)
        fclose(f);
    files[n] = NULL;
    return files;
}
