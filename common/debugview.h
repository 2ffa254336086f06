/* debugview.h: pictures of what a ray finds first instead of its light: raytra --view NAME. */
#ifndef RAYTRA_DEBUGVIEW_H
#define RAYTRA_DEBUGVIEW_H

#include <stdbool.h>
#include <stdio.h>

#include "color.h"
#include "image.h"
#include "vec3.h"

/* What a part tells about the first surface a pixel's camera ray meets. */
typedef struct {
    bool hit;           /* the ray met a surface; the rest is unset when not */
    double t;           /* the ray parameter of the hit (unit direction: the distance) */
    Vec3 normal;        /* the shading normal, facing the ray */
    int surface;        /* a number that tells the surfaces apart */
    Color kd;           /* the diffuse colour shaded with */
    int lights_visible; /* lights that reach the point (in front, not in shadow) */
    long tests;         /* boxes and primitives tested for the ray (from part 1.4) */
} Probe;

/* Fills probe for pixel (i, j), counted as a PixelFn counts them. */
typedef void (*ProbeFn)(const void *ctx, int i, int j, Probe *probe);

typedef enum {
    VIEW_NONE,
    VIEW_NORMAL,
    VIEW_DEPTH,
    VIEW_ID,
    VIEW_MATERIAL,
    VIEW_LIGHT_COUNT,
    VIEW_BOX_TESTS
} ViewKind;

bool debugview_from_name(const char *name, ViewKind *kind);
bool debugview_drawn_by(ViewKind kind, unsigned views_drawn, const char **why);
const char *debugview_names(void);
Color debugview_color(ViewKind kind, const Probe *probe);
void debugview_finish(ViewKind kind, Image *img, int light_count, FILE *messages);

#endif
