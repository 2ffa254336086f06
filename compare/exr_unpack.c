/* exr_unpack.c: undoing the compression of an OpenEXR chunk: RLE, or ZIPS and ZIP through zlib. */
#include "exr_unpack.h"

#include <string.h>
#include <zlib.h>

#include "exr.h"

/* Undoes RLE: runs of a repeated byte (count - 1, then the byte) and of bytes as they
 * are (-count, then the bytes); false unless exactly n bytes come out. */
static bool unrle(const unsigned char *in, size_t size, unsigned char *out, size_t n)
{
    size_t done = 0;
    for (size_t k = 0; k < size;) {
        int count = (signed char)in[k++];
        if (count < 0) {
            size_t run = (size_t)-count;
            if (k + run > size || done + run > n)
                return false;
            memcpy(out + done, in + k, run);
            k += run;
            done += run;
        } else {
            if (k >= size || done + (size_t)count + 1 > n)
                return false;
            memset(out + done, in[k++], (size_t)count + 1);
            done += (size_t)count + 1;
        }
    }
    return done == n;
}

/* Undoes ZIP's and RLE's preparation of n bytes (see exr.c): the differences summed, then
 * the first and second halves interleaved again, into out. */
static void unprepare(unsigned char *in, size_t n, unsigned char *out)
{
    for (size_t k = 1; k < n; k++)
        in[k] = (unsigned char)(in[k - 1] + in[k] - 128);
    size_t half = (n + 1) / 2;
    for (size_t k = 0; k < half; k++)
        out[2 * k] = in[k];
    for (size_t k = 0; k < n / 2; k++)
        out[2 * k + 1] = in[half + k];
}

/* Turns a chunk's packed bytes (packed of them in in), compressed by compression, into its
 * n raw bytes in out, work holding n bytes on the way; false when they do not decompress to
 * exactly n bytes. */
bool exr_unpack(int compression, unsigned char *in, size_t packed, unsigned char *work,
                unsigned char *out, size_t n)
{
    if (packed == n) { /* stored as they are */
        memcpy(out, in, n);
        return true;
    }
    if (compression == EXR_NONE || packed > n)
        return false;
    if (compression == EXR_RLE) {
        if (!unrle(in, packed, work, n))
            return false;
    } else {
        uLongf size = (uLongf)n;
        if (uncompress(work, &size, in, (uLong)packed) != Z_OK || size != n)
            return false;
    }
    unprepare(work, n, out);
    return true;
}
