/* render.h: the parallel render loop: every pixel once, by any number of threads. */
#ifndef RAYTRA_RENDER_H
#define RAYTRA_RENDER_H

#include <stdbool.h>

#include "color.h"
#include "image.h"

/* The kinds of rays the summary line counts. */
typedef enum { RAY_PRIMARY, RAY_SHADOW, RAY_REFLECTED, RAY_REFRACTED, RAY_KIND_COUNT } RayKind;

typedef struct {
    unsigned long long rays[RAY_KIND_COUNT];
} RayStats;

/* Returns the colour of pixel (i, j), counting the rays it traces into stats.
 * i counts columns from the left and j rows from the bottom, as in the
 * lecture; the loop stores the result in image row height - 1 - j. Calls for
 * different pixels may run at once on different threads. */
typedef Color (*PixelFn)(const void *ctx, int i, int j, RayStats *stats);

typedef struct {
    PixelFn pixel;
    const void *ctx; /* handed to pixel, shared by every thread: read only */
    int threads;     /* how many threads render; at least 1 */
    bool progress;   /* draw a progress bar on stderr */
} RenderJob;

typedef struct {
    RayStats stats;
    double seconds;
    long nonfinite; /* pixels whose colour was NaN, infinite or beyond float range,
                       stored magenta (1, 0, 1) */
    int first_nonfinite_x, first_nonfinite_y;
    bool stopped;   /* a stop was requested (stop.h): the image is incomplete */
    bool abandoned; /* stopped, and workers still busy with a pixel were given up: they go
                       on writing the image and reading the job's ctx, so the caller frees
                       nothing and ends the process at once (_exit) */
} RenderResult;

void render_image(Image *img, const RenderJob *job, RenderResult *result);
bool render_call(void (*fn)(void *arg), void *arg);
bool render_idle(void);
int render_default_threads(void);
unsigned long long render_total_rays(const RayStats *stats);
const char *render_ray_kind_name(RayKind kind);

#endif
