/* grade_path.c: the disk as the grader meets it: a path's kind, folders, files compared and opened. */
#include "grade_path.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "grade_base.h"
#include "imgfile.h"

/* Returns the kind of the file at path, links followed: S_IFDIR, S_IFREG...; 0 for none. */
int path_kind(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 ? (int)(st.st_mode & S_IFMT) : 0;
}

/* Makes the folder path, refusing anything already there (a link a student left). */
bool path_make_folder(const char *path)
{
    return mkdir(path, 0777) == 0 ||
           grade_fail("cannot make the folder %s: %s", path, strerror(errno));
}

/* Makes the folder path anew for the grader's work. Anything already there (a folder or a
 * link that a student's program made) is moved aside, renamed, never followed, to a hidden
 * .moved-N-NAME beside it, told on `notes`. Returns NULL, or why the folder was not made. */
const char *path_fresh_folder(const char *path, FILE *notes)
{
    struct stat st;
    const char *slash = strrchr(path, '/');
    for (int n = 1; lstat(path, &st) == 0; n++) {
        char *aside = grade_format("%.*s/.moved-%d-%s", (int)(slash - path), path, n, slash + 1);
        if (n > 100)
            return grade_format("%s is there already and cannot be moved aside", path);
        if (lstat(aside, &st) == 0 || errno != ENOENT)
            continue;
        if (rename(path, aside) != 0)
            return grade_format("cannot move %s aside: %s", path, strerror(errno));
        fprintf(notes,
                "grade: note: %s was there before grade made it (a program of the class made "
                "it?): moved aside to %s\n",
                path, aside);
    }
    return mkdir(path, 0777) == 0 ? NULL
                                  : grade_format("cannot make %s: %s", path, strerror(errno));
}

/* Returns the names of the folders in `folder`, hidden ones left out, in strcmp's order;
 * sets *count. NULL (and errno) when the folder cannot be read. */
char **path_list_folders(const char *folder, int *count)
{
    struct dirent **entries;
    int n = scandir(folder, &entries, NULL, alphasort);
    char **names = n >= 0 ? grade_alloc(((size_t)n + 1) * sizeof *names) : NULL;
    *count = 0;
    for (int k = 0; k < n; k++) {
        const char *name = entries[k]->d_name;
        if (name[0] != '.' && path_kind(grade_format("%s/%s", folder, name)) == S_IFDIR)
            names[(*count)++] = grade_format("%s", name);
        free(entries[k]);
    }
    if (n >= 0)
        free(entries);
    return names;
}

/* Tells whether the files at a and b hold the same bytes (both opened as a student's file). */
bool path_same_bytes(const char *a, const char *b)
{
    FILE *fa = imgfile_fopen(a), *fb = imgfile_fopen(b);
    struct stat sa, sb;
    bool same = fa != NULL && fb != NULL && fstat(fileno(fa), &sa) == 0 &&
                fstat(fileno(fb), &sb) == 0 && sa.st_size == sb.st_size;
    char ca[1 << 14], cb[1 << 14];
    for (size_t n; same && (n = fread(ca, 1, sizeof ca, fa)) > 0;)
        same = fread(cb, 1, n, fb) == n && memcmp(ca, cb, n) == 0;
    same = same && !ferror(fa);
    if (fa != NULL)
        fclose(fa);
    if (fb != NULL)
        fclose(fb);
    return same;
}

/* Opens the file at path to read when it is a regular file, never blocking on a FIFO nor
 * following a symbolic link; NULL when it cannot, with *kind the file's kind in words when
 * it is there but not a regular file, else NULL (errno says why). */
FILE *path_open_regular(const char *path, const char **kind)
{
    struct stat st;
    *kind = NULL;
    if (lstat(path, &st) == 0 && !S_ISREG(st.st_mode)) {
        *kind = imgfile_kind_text(st.st_mode);
        return NULL;
    }
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOFOLLOW | O_CLOEXEC), flags;
    bool opened = fd >= 0 && fstat(fd, &st) == 0;
    FILE *f = NULL;
    /* Checked again on the descriptor: the path may have changed since lstat. */
    if (opened && !S_ISREG(st.st_mode))
        *kind = imgfile_kind_text(st.st_mode);
    else if (opened && (flags = fcntl(fd, F_GETFL)) >= 0 &&
             fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) == 0)
        f = fdopen(fd, "r");
    if (fd >= 0 && f == NULL)
        close(fd);
    return f;
}
