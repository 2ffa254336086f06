/* grade_thumb.h: the PNG pictures the report embeds, made from any image imgdiff reads. */
#ifndef RAYTRA_GRADE_THUMB_H
#define RAYTRA_GRADE_THUMB_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

/* The longest side of a thumbnail: three fit side by side on a laptop's screen. */
#define THUMB_SIDE 320

/* The largest image shown: a larger one is surely a mistake, or a decompression bomb. */
#define THUMB_MAX_PIXELS (4096L * 4096)

/* How a thumbnail shrinks a block of pixels into one. */
typedef enum {
    THUMB_MEAN,  /* the block's mean: for pictures */
    THUMB_PEAKS, /* its brightest pixel: a heat map's single differing pixel must stay */
} ThumbKind;

/* A PNG thumbnail read for embedding: its bytes and its size in pixels. */
typedef struct {
    unsigned char *data;
    size_t size;
    int width, height;
} Thumb;

bool thumb_make(const char *from, const char *to, int max_side, ThumbKind kind, const char *log,
                long long memory_limit);
bool thumb_read(const char *path, Thumb *p);
void thumb_write_uri(FILE *f, Thumb *p);

#endif
