/* driver.c: runs a fuzzing harness on files, without libFuzzer: the regression tests. */
#include <dirent.h>
#include <limits.h>
#include <stdbool.h>
#include <string.h>
#include <sys/stat.h>

#include "fuzz.h"

/* The inputs to run, as absolute paths: the harness may change the working folder. */
typedef struct {
    char **path;
    int count, capacity;
} Inputs;

/* Adds the file at path (made absolute) to the inputs; false when it cannot be found. */
static bool add_input(Inputs *in, const char *path)
{
    char *full = realpath(path, NULL);
    if (full == NULL) {
        perror(path);
        return false;
    }
    if (in->count == in->capacity) {
        in->capacity = in->capacity > 0 ? 2 * in->capacity : 64;
        in->path = realloc(in->path, (size_t)in->capacity * sizeof *in->path);
        FUZZ_CHECK(in->path != NULL);
    }
    in->path[in->count++] = full;
    return true;
}

/* Adds a file, or every file of a folder (not its subfolders), to the inputs. */
static bool add_argument(Inputs *in, const char *path)
{
    struct stat st;
    if (stat(path, &st) != 0 || !S_ISDIR(st.st_mode))
        return add_input(in, path);
    DIR *dir = opendir(path);
    if (dir == NULL) {
        perror(path);
        return false;
    }
    bool ok = true;
    for (struct dirent *e; (e = readdir(dir)) != NULL;) {
        char file[PATH_MAX];
        snprintf(file, sizeof file, "%s/%s", path, e->d_name);
        if (e->d_name[0] != '.' && stat(file, &st) == 0 && S_ISREG(st.st_mode))
            ok = add_input(in, file) && ok;
    }
    closedir(dir);
    return ok;
}

/* Reads the whole file at path into a new buffer; NULL when it cannot. */
static uint8_t *read_input(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    if (f == NULL)
        return NULL;
    uint8_t *data = NULL;
    size_t used = 0, capacity = 0, n;
    do {
        if (used == capacity) {
            capacity = capacity > 0 ? 2 * capacity : 4096;
            data = realloc(data, capacity);
            FUZZ_CHECK(data != NULL);
        }
        n = fread(data + used, 1, capacity - used, f);
        used += n;
    } while (n > 0);
    bool failed = ferror(f);
    fclose(f);
    if (failed) {
        free(data);
        return NULL;
    }
    *size = used;
    return data;
}

/* Runs the harness on every file named, or in a folder named, on the command line. */
int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: %s FILE-OR-FOLDER...\n", argv[0]);
        return 2;
    }
    Inputs in = {0};
    bool ok = true;
    for (int k = 1; k < argc; k++)
        ok = add_argument(&in, argv[k]) && ok;
    LLVMFuzzerInitialize(&argc, &argv);
    for (int k = 0; k < in.count; k++) {
        size_t size;
        uint8_t *data = read_input(in.path[k], &size);
        if (data == NULL) {
            perror(in.path[k]);
            ok = false;
        } else {
            LLVMFuzzerTestOneInput(data, size);
            free(data);
        }
        free(in.path[k]);
    }
    free(in.path);
    printf("%s: %d inputs run\n", argv[0], in.count);
    return ok ? 0 : 1;
}
