/* exr_unpack.h: undoing the compression of an OpenEXR chunk: RLE, or ZIPS and ZIP through zlib. */
#ifndef RAYTRA_EXR_UNPACK_H
#define RAYTRA_EXR_UNPACK_H

#include <stdbool.h>
#include <stddef.h>

bool exr_unpack(int compression, unsigned char *in, size_t packed, unsigned char *work,
                unsigned char *out, size_t n);

#endif
