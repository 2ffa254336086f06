/* imgdiff.h: imgdiff's default tolerances, which the image-regression tests use. */
#ifndef RAYTRA_IMGDIFF_H
#define RAYTRA_IMGDIFF_H

/* A pixel counts as different when one of its channels differs by more than 2 steps of
 * 8 bits: a step or two is what another compiler or maths library may change. */
#define IMGDIFF_THRESHOLD (2.0 / 255.0)
#define IMGDIFF_THRESHOLD_TEXT "2/255"

/* Two images match when at most this fraction (0.1%) of the pixels differ: a few pixels
 * on an edge may fall on the other side of it. */
#define IMGDIFF_ALLOW 0.001
#define IMGDIFF_ALLOW_TEXT "0.001"

#endif
