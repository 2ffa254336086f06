/* input.h: opening the files raytra reads (scenes, meshes): regular files and pipes only. */
#ifndef RAYTRA_INPUT_H
#define RAYTRA_INPUT_H

#include <stdbool.h>
#include <stdio.h>
#include <sys/types.h>

#include "diag.h"

/* Which file was read: the same device and inode is the same file, whatever its name. */
typedef struct {
    dev_t device;
    ino_t inode;
    char *path; /* as it was opened, for messages */
} FileId;

FILE *input_open(const char *path, const char *what, bool pipe_ok, FileId *id, Error *err);
bool input_same_file(const FileId *id, const char *path);

#endif
