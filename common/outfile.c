/* outfile.c: files that appear only when complete: a temporary, renamed onto the name. */
#include "outfile.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "stop.h"

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

/* Tells whether a file can be written at path, so that a long render is not wasted;
 * reports why not otherwise. */
bool outfile_check(const char *path, Error *err)
{
    size_t len = strlen(path);
    if (len == 0 || path[len - 1] == '/') {
        error_set(err, "not a file name");
        return false;
    }
    struct stat st;
    if (stat(path, &st) == 0) {
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
    if (folder == NULL) {
        error_set(err, "out of memory");
        return false;
    }
    bool ok = check_folder(folder, err);
    free(folder);
    return ok;
}

/* Opens a new hidden temporary ".NAME.XXXXXX" beside path, where out->file writes. */
bool outfile_open(OutFile *out, const char *path, Error *err)
{
    *out = (OutFile){0};
    if (!outfile_check(path, err))
        return false;
    /* In the same folder, as only a rename within one file system replaces a file in one
     * step: readers see the old file or the new one, never half of it. */
    const char *slash = strrchr(path, '/');
    int folder_len = slash != NULL ? (int)(slash - path) + 1 : 0;
    size_t size = strlen(path) + sizeof "..XXXXXX";
    out->path = strdup(path);
    out->temp_path = malloc(size);
    if (out->path == NULL || out->temp_path == NULL) {
        outfile_abort(out);
        error_set(err, "out of memory");
        return false;
    }
    snprintf(out->temp_path, size, "%.*s.%s.XXXXXX", folder_len, path, path + folder_len);
    int fd = mkstemp(out->temp_path);
    if (fd < 0) {
        error_set(err, "cannot make a temporary file beside it: %s", strerror(errno));
        /* The name may now be anyone's file: it must not be unlinked. */
        free(out->temp_path);
        out->temp_path = NULL;
        outfile_abort(out);
        return false;
    }
    /* mkstemp makes the file private (0600); the image should get the permissions any
     * new file gets. The umask can only be read by setting it, so set it back at once
     * (to a strict value meanwhile, in case another thread makes a file). */
    mode_t mask = umask(077);
    umask(mask);
    if (fchmod(fd, 0666 & ~mask) != 0 || (out->file = fdopen(fd, "wb")) == NULL) {
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
    if (unlink(out->temp_path) != 0 && errno != ENOENT) {
        size_t len = strlen(err->text);
        snprintf(err->text + len, sizeof err->text - len,
                 " (and the temporary '%s' could not be removed)", out->temp_path);
    }
    free(out->temp_path);
    out->temp_path = NULL;
    outfile_abort(out);
}

/* Flushes the file to the disk, checking every step (a full disk shows only here), and
 * renames it onto path; on failure or a stop request, it leaves nothing and path as it was.
 */
bool outfile_commit(OutFile *out, Error *err)
{
    if (out->file == NULL) {
        error_set(err, "the file is not open");
        outfile_abort(out);
        return false;
    }
    if (stop_requested()) {
        error_set(err, "interrupted");
        discard(out, err);
        return false;
    }
    FILE *f = out->file;
    out->file = NULL;
    errno = 0;
    bool ok = fflush(f) == 0 && !ferror(f) && fsync(fileno(f)) == 0;
    int saved = errno;
    if (fclose(f) != 0 && ok) {
        ok = false;
        saved = errno;
    }
    if (!ok) {
        error_set(err, "%s", saved != 0 ? strerror(saved) : "write error");
        discard(out, err);
        return false;
    }
    if (rename(out->temp_path, out->path) != 0) {
        error_set(err, "cannot rename the temporary file onto it: %s", strerror(errno));
        discard(out, err);
        return false;
    }
    free(out->temp_path);
    free(out->path);
    *out = (OutFile){0};
    return true;
}

/* Closes and removes the temporary, if any, and forgets out; leaves path as it was. */
void outfile_abort(OutFile *out)
{
    if (out->file != NULL)
        fclose(out->file);
    if (out->temp_path != NULL)
        unlink(out->temp_path);
    free(out->temp_path);
    free(out->path);
    *out = (OutFile){0};
}
