/* imgfile.c: what kind of image a file holds, told by its first bytes, whatever its name. */
#include "imgfile.h"

#include <stdio.h>

/* Tells whether the file at path is a PFM ("PF" for colour, "Pf" for grey): its values
 * are linear, where a PNG's are as stored, so the two are compared with care. */
bool imgfile_is_pfm(const char *path)
{
    char magic[2];
    FILE *f = fopen(path, "rb");
    bool pfm = f != NULL && fread(magic, 1, 2, f) == 2 && magic[0] == 'P' &&
               (magic[1] == 'F' || magic[1] == 'f');
    if (f != NULL)
        fclose(f);
    return pfm;
}
