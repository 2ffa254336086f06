/* mcref.h: statistical references of Monte Carlo renders, mean and variance per pixel, in OpenEXR.
 */
#ifndef RAYTRA_MCREF_H
#define RAYTRA_MCREF_H

#include <stdbool.h>

#include "diag.h"

/* The planes of a reference, each three floats (R, G, B) a pixel, rows from the top. */
typedef enum {
    MCREF_MEAN,     /* linear: the mean of the renders (channels R, G, B) */
    MCREF_VAR,      /* linear: the variance of one render (variance.R, .G, .B) */
    MCREF_CODE,     /* 8-bit sRGB code values, 0 to 255: their mean (code.R, .G, .B) */
    MCREF_CODE_VAR, /* the variance of one render's code values (codevariance.R, .G, .B) */
    MCREF_PLANES
} McRefPlane;

/* A statistical reference: what raytra's estimate of each pixel at P S converges to, and
 * how much one render of it varies, from renders with independent seeds. */
typedef struct {
    int width, height;
    int p, s;             /* the part's P and S the renders were made with */
    int mean_samples;     /* renders averaged into the means */
    int variance_samples; /* renders the variances are estimated from */
    char seeds[64];       /* their seeds, "1000-1063" */
    float *plane[MCREF_PLANES];
} McRef;

bool mcref_init(McRef *ref, int width, int height);
void mcref_free(McRef *ref);
bool mcref_is(const char *path);
bool mcref_read(McRef *ref, const char *path, Error *err);
bool mcref_write(const McRef *ref, const char *path, Error *err);

#endif
