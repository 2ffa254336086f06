/* grade_thumb.c: shrinking images into PNG thumbnails, in a child, and embedding them in HTML. */
#include "grade_thumb.h"

#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>

#include "grade.h"
#include "grade_run.h"
#include "image.h"
#include "imgfile.h"

/* The largest picture embedded: thumbnails are far smaller; a larger file is a mistake. */
#define EMBED_MAX_BYTES (8L << 20)

/* What one thumbnail is made from and how. */
typedef struct {
    const char *from, *to;
    int max_side; /* 0: the full size */
    ThumbKind kind;
} ThumbJob;

/* Returns the brightness by which THUMB_PEAKS picks a block's pixel. */
static double brightness(Color c)
{
    return c.r + c.g + c.b;
}

/* Returns the colour of the block of src from (x0, y0) up to (x1, y1), not included. */
static Color shrink_block(const Image *src, int x0, int y0, int x1, int y1, ThumbKind kind)
{
    Color sum = color(0, 0, 0), peak = image_get(src, x0, y0);
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            Color c = image_get(src, x, y);
            sum = color_add(sum, c);
            if (brightness(c) > brightness(peak))
                peak = c;
        }
    return kind == THUMB_PEAKS ? peak : color_scale(sum, 1.0 / ((x1 - x0) * (y1 - y0)));
}

/* Reads job->from, shrinks it by a whole factor to fit job->max_side and writes it as a
 * PNG; runs in a child (run_function), so returns an exit status, reasons on stderr. */
static int thumb_job(void *arg)
{
    const ThumbJob *job = arg;
    Image src, dst;
    Error err;
    ImgFileKind kind;
    int w, h;
    if (!imgfile_header(job->from, &kind, &w, &h, &err)) {
        fprintf(stderr, "%s\n", err.text);
        return 1;
    }
    if ((long)w * h > THUMB_MAX_PIXELS) {
        fprintf(stderr, "%d x %d pixels: too large to show\n", w, h);
        return 1;
    }
    if (!image_read(&src, job->from, &err)) {
        fprintf(stderr, "%s\n", err.text);
        return 1;
    }
    int side = src.width > src.height ? src.width : src.height;
    int factor = job->max_side > 0 ? (side + job->max_side - 1) / job->max_side : 1;
    if (!image_init(&dst, (src.width + factor - 1) / factor, (src.height + factor - 1) / factor)) {
        fprintf(stderr, "not enough memory for the thumbnail\n");
        return 1;
    }
    for (int y = 0; y < dst.height; y++)
        for (int x = 0; x < dst.width; x++) {
            int x1 = (x + 1) * factor < src.width ? (x + 1) * factor : src.width;
            int y1 = (y + 1) * factor < src.height ? (y + 1) * factor : src.height;
            image_set(&dst, x, y, shrink_block(&src, x * factor, y * factor, x1, y1, job->kind));
        }
    /* A PNG's values are read as stored and go back as they were; a PFM's are linear
     * radiance, encoded as raytra encodes its PNGs, so that it can be compared with one. */
    PngEncoding encoding = kind == IMGFILE_PNG ? PNG_ENCODING_LINEAR : PNG_ENCODING_SRGB;
    /* Written directly, without image_write's temporary and flush to the disk: the grader
     * uses the file only when this child reports success. */
    int fd = open(job->to, O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_NONBLOCK, 0644);
    FILE *f = fd >= 0 ? fdopen(fd, "wb") : NULL;
    bool ok = f != NULL && image_write_png(&dst, f, encoding, &err);
    if (f != NULL && fclose(f) != 0)
        ok = false;
    if (!ok)
        fprintf(stderr, "cannot write '%s'\n", job->to);
    image_free(&dst);
    image_free(&src);
    return ok ? 0 : 1;
}

/* Writes to `to` a PNG of the image `from` shrunk to fit max_side (0: full size), in a
 * child with a time limit and the memory limit, since `from` may be a student's file;
 * reasons go to log. Returns whether it did. */
bool thumb_make(const char *from, const char *to, int max_side, ThumbKind kind, const char *log,
                long long memory_limit)
{
    ThumbJob job = {from, to, max_side, kind};
    RunSpec spec = {.log = log, .time_limit = 120, .memory_limit = RUN_OWN_MEMORY(memory_limit)};
    RunResult r = run_function(thumb_job, &job, &spec);
    return r.end == RUN_EXITED && r.status == 0;
}

/* Reads the whole file at path, if it is at most EMBED_MAX_BYTES; NULL otherwise. */
static unsigned char *read_small_file(const char *path, size_t *size)
{
    struct stat st;
    FILE *f = imgfile_fopen(path);
    unsigned char *data = NULL;
    if (f != NULL && fstat(fileno(f), &st) == 0 && st.st_size <= EMBED_MAX_BYTES) {
        data = grade_alloc((size_t)st.st_size + 1);
        *size = fread(data, 1, (size_t)st.st_size, f);
        if (ferror(f) || *size != (size_t)st.st_size) {
            free(data);
            data = NULL;
        }
    }
    if (f != NULL)
        fclose(f);
    return data;
}

/* Writes the bytes data[0..size) in base64. */
static void write_base64(FILE *f, const unsigned char *data, size_t size)
{
    static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    for (size_t i = 0; i < size; i += 3) {
        unsigned long bits = (unsigned long)data[i] << 16;
        if (i + 1 < size)
            bits |= (unsigned long)data[i + 1] << 8;
        if (i + 2 < size)
            bits |= data[i + 2];
        fputc(digits[(bits >> 18) & 63], f);
        fputc(digits[(bits >> 12) & 63], f);
        fputc(i + 1 < size ? digits[(bits >> 6) & 63] : '=', f);
        fputc(i + 2 < size ? digits[bits & 63] : '=', f);
    }
}

/* Reads the PNG at path (a thumbnail the grader made) into p; false when it cannot. */
bool thumb_read(const char *path, Thumb *p)
{
    ImgFileKind kind;
    Error err;
    *p = (Thumb){0};
    return path != NULL && imgfile_header(path, &kind, &p->width, &p->height, &err) &&
           kind == IMGFILE_PNG && (p->data = read_small_file(path, &p->size)) != NULL;
}

/* Writes picture p as a data: URI, and frees its bytes. */
void thumb_write_uri(FILE *f, Thumb *p)
{
    fputs("data:image/png;base64,", f);
    write_base64(f, p->data, p->size);
    free(p->data);
}
