/* input.c: opening the files raytra reads: regular files and pipes, never a device or a folder. */
#include "input.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

/* Returns why a file of this type cannot be read as text, or NULL when it can: a regular
 * file, or when pipe_ok a pipe (a FIFO or a shell's <(...)), which ends when its writer
 * closes it. A device may never end (/dev/zero, /dev/urandom) or wait for ever (a
 * terminal), and so may a FIFO nobody writes to. */
static const char *unreadable_type(mode_t mode, bool pipe_ok)
{
    if (S_ISREG(mode) || (pipe_ok && S_ISFIFO(mode)))
        return NULL;
    if (S_ISFIFO(mode))
        return "is a named pipe";
    if (S_ISDIR(mode))
        return "is a directory";
    if (S_ISCHR(mode) || S_ISBLK(mode))
        return "is a device";
    if (S_ISSOCK(mode))
        return "is a socket";
    return "is not a regular file";
}

/* Returns the indefinite article of noun: "an OBJ file", "a scene file". */
static const char *article(const char *noun)
{
    return strchr("AEIOUaeiou", noun[0]) != NULL ? "an" : "a";
}

/* Opens path for reading as a what ("scene file", "OBJ file"), a regular file or, when
 * pipe_ok, a pipe (opening one waits for its writer, or for a signal); fills *id with which
 * file it is (its path to free by the caller). NULL (err set) when it cannot be opened or
 * is of another type: the type is checked before opening, so that opening a
 * device has no effect, and again on the open file, in case the name changed meanwhile. */
FILE *input_open(const char *path, const char *what, bool pipe_ok, FileId *id, Error *err)
{
    *id = (FileId){0};
    struct stat st;
    const char *why;
    if (stat(path, &st) == 0 && (why = unreadable_type(st.st_mode, pipe_ok)) != NULL) {
        error_set(err, "%s, not %s %s", why, article(what), what);
        return NULL;
    }
    FILE *f = fopen(path, "r");
    if (f == NULL) {
        error_set(err, "cannot open %s: %s", what, strerror(errno));
        return NULL;
    }
    if (fstat(fileno(f), &st) != 0 || (why = unreadable_type(st.st_mode, pipe_ok)) != NULL) {
        error_set(err, "%s, not %s %s", why ? why : strerror(errno), article(what), what);
        fclose(f);
        return NULL;
    }
    id->device = st.st_dev;
    id->inode = st.st_ino;
    id->path = strdup(path);
    if (id->path == NULL) {
        error_set(err, "out of memory");
        fclose(f);
        return NULL;
    }
    return f;
}

/* Tells whether path names the file id, through any link or spelling. */
bool input_same_file(const FileId *id, const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && st.st_dev == id->device && st.st_ino == id->inode;
}
