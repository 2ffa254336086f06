/* imgfile.h: what kind of image a file holds, told by its first bytes, whatever its name. */
#ifndef RAYTRA_IMGFILE_H
#define RAYTRA_IMGFILE_H

#include <stdbool.h>

bool imgfile_is_pfm(const char *path);

#endif
