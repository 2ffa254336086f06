/* outfile.c: files that appear only when complete: a temporary, unnamed if possible, then named. */
/* O_TMPFILE and linkat's AT_SYMLINK_FOLLOW on /proc/self/fd are Linux's: asked for here. */
#define _GNU_SOURCE
#include "outfile.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "stop.h"

bool outfile_avoid_tmpfile;

/* Returns a copy of path's folder ("." when it names none); NULL when out of memory. */
static char *folder_of(const char *path)
{
    const char *slash = strrchr(path, '/');
    if (slash == NULL)
        return strdup(".");
    if (slash == path)
        return strdup("/");
    return strndup(path, (size_t)(slash - path));
}

/* Tells whether files can be made in folder; reports why not otherwise. */
static bool check_folder(const char *folder, Error *err)
{
    struct stat st;
    if (stat(folder, &st) != 0) {
        if (errno == ENOENT)
            error_set(err, "folder '%s' does not exist", folder);
        else if (errno == ENOTDIR)
            error_set(err, "'%s' is not a folder", folder);
        else
            error_set(err, "folder '%s': %s", folder, strerror(errno));
        return false;
    }
    if (!S_ISDIR(st.st_mode)) {
        error_set(err, "'%s' is not a folder", folder);
        return false;
    }
    /* Making a file needs write permission, and reaching it search (x) permission. */
    if (access(folder, W_OK | X_OK) != 0) {
        error_set(err, "folder '%s' is not writable", folder);
        return false;
    }
    return true;
}

/* Returns the length of the longest file name the folder takes (NAME_MAX, usually 255). */
static long name_max(const char *folder)
{
    errno = 0;
    long n = pathconf(folder, _PC_NAME_MAX);
    return n > 0 ? n : 255;
}

/* Opens a new temporary file in folder for writing: unnamed (O_TMPFILE) where the system
 * and the file system can, so that nothing is left if raytra is killed; otherwise a hidden
 * named one made from template (which mkstemp fills in). Returns its descriptor, or -1
 * (errno set); *named tells which. */
static int open_temporary(const char *folder, char *template, bool *named)
{
    *named = false;
#ifdef O_TMPFILE
    /* linkat gives the file a name through /proc/self/fd: without /proc it could not. */
    if (!outfile_avoid_tmpfile && access("/proc/self/fd", X_OK) == 0) {
        int fd = open(folder, O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
        if (fd >= 0)
            return fd;
        /* Only "not supported here" falls back; a real refusal (EACCES) is the answer. */
        if (errno != EOPNOTSUPP && errno != EISDIR && errno != EINVAL)
            return -1;
    }
#endif
    int fd = mkstemp(template);
    if (fd < 0)
        return -1;
    *named = true;
    /* mkstemp makes the file private (0600); the image should get the permissions any
     * new file gets. The umask can only be read by setting it, so set it back at once
     * (to a strict value meanwhile, in case another thread makes a file). */
    mode_t mask = umask(077);
    umask(mask);
    if (fchmod(fd, 0666 & ~mask) != 0) {
        int saved = errno;
        close(fd);
        unlink(template);
        errno = saved;
        return -1;
    }
    return fd;
}

/* Returns, to free, the name of a hidden temporary beside path, ending in XXXXXX for
 * mkstemp: ".NAME.XXXXXX", or ".raytra.XXXXXX" when that would be too long a name. */
static char *temporary_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    int folder_len = slash != NULL ? (int)(slash - path) + 1 : 0;
    const char *name = path + folder_len;
    char *folder = folder_of(path);
    long max = folder != NULL ? name_max(folder) : 255;
    free(folder);
    size_t size = strlen(path) + sizeof ".raytra..XXXXXX";
    char *temp = malloc(size);
    if (temp == NULL)
        return NULL;
    if ((long)strlen(name) + (long)sizeof "..XXXXXX" - 1 <= max)
        snprintf(temp, size, "%.*s.%s.XXXXXX", folder_len, path, name);
    else
        snprintf(temp, size, "%.*s.raytra.XXXXXX", folder_len, path);
    return temp;
}

/* Tells whether a file can be written at path, so that a long render is not wasted;
 * reports why not otherwise. It tries what the write will do: it makes a temporary file
 * in the folder and removes it, checks the name's length, and whether the folder lets
 * the file be replaced. */
bool outfile_check(const char *path, Error *err)
{
    size_t len = strlen(path);
    if (len == 0 || path[len - 1] == '/') {
        error_set(err, "not a file name");
        return false;
    }
    if (len >= PATH_MAX) {
        error_set(err, "the path is longer than %d characters", PATH_MAX - 1);
        return false;
    }
    struct stat st;
    bool exists = stat(path, &st) == 0;
    if (exists) {
        if (S_ISDIR(st.st_mode)) {
            error_set(err, "it is a folder");
            return false;
        }
        /* The rename would replace a device such as /dev/null by a plain file. */
        if (!S_ISREG(st.st_mode)) {
            error_set(err, "it exists and is not a regular file");
            return false;
        }
        if (access(path, W_OK) != 0) {
            error_set(err, "the file exists and is not writable");
            return false;
        }
    }
    char *folder = folder_of(path);
    char *temp = temporary_name(path);
    if (folder == NULL || temp == NULL) {
        free(folder);
        free(temp);
        error_set(err, "out of memory");
        return false;
    }
    bool ok = check_folder(folder, err);
    const char *slash = strrchr(path, '/');
    const char *name = slash != NULL ? slash + 1 : path;
    long max = name_max(folder);
    if (ok && (long)strlen(name) > max) {
        error_set(err, "the name is %zu characters long; the folder takes at most %ld",
                  strlen(name), max);
        ok = false;
    }
    /* In a sticky folder (such as /tmp) only the file's owner, the folder's or root may
     * replace a file: the final rename would be refused after the whole render. */
    struct stat fst;
    uid_t me = geteuid();
    if (ok && exists && stat(folder, &fst) == 0 && (fst.st_mode & S_ISVTX) && me != 0 &&
        st.st_uid != me && fst.st_uid != me) {
        error_set(err, "the file belongs to another user, in a folder where only its owner may "
                       "replace it (sticky, like /tmp)");
        ok = false;
    }
    if (ok) {
        bool named;
        int fd = open_temporary(folder, temp, &named);
        if (fd < 0) {
            error_set(err, "cannot make a temporary file beside it: %s", strerror(errno));
            ok = false;
        } else {
            close(fd);
            if (named)
                unlink(temp);
        }
    }
    free(folder);
    free(temp);
    return ok;
}

/* Opens a new temporary beside path, where out->file writes: unnamed where the system can
 * (see open_temporary), so that a kill leaves nothing; else hidden ".NAME.XXXXXX". */
bool outfile_open(OutFile *out, const char *path, Error *err)
{
    *out = (OutFile){0};
    if (!outfile_check(path, err))
        return false;
    /* In the same folder, as only a rename within one file system replaces a file in one
     * step: readers see the old file or the new one, never half of it. */
    out->path = strdup(path);
    out->folder = folder_of(path);
    out->temp_path = temporary_name(path);
    if (out->path == NULL || out->folder == NULL || out->temp_path == NULL) {
        outfile_abort(out);
        error_set(err, "out of memory");
        return false;
    }
    bool named;
    int fd = open_temporary(out->folder, out->temp_path, &named);
    if (fd < 0) {
        error_set(err, "cannot make a temporary file beside it: %s", strerror(errno));
        /* The name may now be anyone's file: it must not be unlinked. */
        free(out->temp_path);
        out->temp_path = NULL;
        outfile_abort(out);
        return false;
    }
    if (!named) {
        /* The template is kept to name the file when it is complete. */
        out->unnamed_fd = fd;
        out->unnamed = true;
        free(out->temp_path);
        out->temp_path = NULL;
    }
    if ((out->file = fdopen(fd, "wb")) == NULL) {
        error_set(err, "cannot open the temporary file: %s", strerror(errno));
        close(fd);
        outfile_abort(out);
        return false;
    }
    return true;
}

/* Forgets out after a failed commit; a temporary that cannot be removed (in a folder
 * made read-only meanwhile) is named in the message, so that the user can remove it. */
static void discard(OutFile *out, Error *err)
{
    if (out->temp_path != NULL && unlink(out->temp_path) != 0 && errno != ENOENT) {
        size_t len = strlen(err->text);
        snprintf(err->text + len, sizeof err->text - len,
                 " (and the temporary '%s' could not be removed)", out->temp_path);
    }
    free(out->temp_path);
    out->temp_path = NULL;
    outfile_abort(out);
}

/* Gives the complete unnamed file of out a name: path itself when nothing is there (one
 * step), else a fresh hidden name beside it, to be renamed onto path (linkat cannot
 * replace a file). Sets out->temp_path in that case; false (errno set) on failure. */
static bool link_unnamed(OutFile *out)
{
    char proc[64];
    snprintf(proc, sizeof proc, "/proc/self/fd/%d", out->unnamed_fd);
    if (linkat(AT_FDCWD, proc, AT_FDCWD, out->path, AT_SYMLINK_FOLLOW) == 0) {
        out->linked = true;
        return true;
    }
    if (errno != EEXIST)
        return false;
    char *temp = temporary_name(out->path);
    if (temp == NULL) {
        errno = ENOMEM;
        return false;
    }
    /* mkstemp's letters, drawn here: the name must not exist, as linkat does not replace. */
    static const char letters[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    uint64_t seed = (uint64_t)time(NULL) ^ ((uint64_t)getpid() << 20) ^ (uintptr_t)temp;
    char *x = temp + strlen(temp) - 6;
    for (int attempt = 0; attempt < 100; attempt++) {
        for (int k = 0; k < 6; k++) {
            seed = seed * 6364136223846793005u + 1442695040888963407u;
            x[k] = letters[(seed >> 33) % (sizeof letters - 1)];
        }
        if (linkat(AT_FDCWD, proc, AT_FDCWD, temp, AT_SYMLINK_FOLLOW) == 0) {
            out->temp_path = temp;
            return true;
        }
        if (errno != EEXIST)
            break;
    }
    int saved = errno;
    free(temp);
    errno = saved;
    return false;
}

/* Flushes the file to the disk, checking every step (a full disk shows only here), and
 * puts it at path; on failure or a stop request, it leaves nothing and path as it was. */
bool outfile_commit(OutFile *out, Error *err)
{
    if (out->file == NULL) {
        error_set(err, "the file is not open");
        outfile_abort(out);
        return false;
    }
    errno = 0;
    bool ok = !stop_requested() && fflush(out->file) == 0 && !ferror(out->file) &&
              fsync(fileno(out->file)) == 0;
    int saved = errno;
    /* A stop request during the sync (which may take seconds) still stops. */
    if (stop_requested()) {
        error_set(err, "interrupted");
        discard(out, err);
        return false;
    }
    if (!ok) {
        error_set(err, "%s", saved != 0 ? strerror(saved) : "write error");
        discard(out, err);
        return false;
    }
    if (out->unnamed && !link_unnamed(out)) {
        error_set(err, "cannot give the file its name: %s", strerror(errno));
        discard(out, err);
        return false;
    }
    FILE *f = out->file;
    out->file = NULL;
    if (fclose(f) != 0) {
        error_set(err, "%s", strerror(errno));
        /* Named path itself, it was not there before: take it back. */
        if (out->linked)
            unlink(out->path);
        discard(out, err);
        return false;
    }
    if (!out->linked && rename(out->temp_path, out->path) != 0) {
        error_set(err, "cannot rename the temporary file onto it: %s", strerror(errno));
        discard(out, err);
        return false;
    }
    free(out->temp_path);
    free(out->path);
    free(out->folder);
    *out = (OutFile){0};
    return true;
}

/* Closes and removes the temporary, if any, and forgets out; leaves path as it was. An
 * unnamed temporary vanishes when closed. */
void outfile_abort(OutFile *out)
{
    if (out->file != NULL)
        fclose(out->file);
    if (out->temp_path != NULL)
        unlink(out->temp_path);
    free(out->temp_path);
    free(out->path);
    free(out->folder);
    *out = (OutFile){0};
}
