/* pixdiff.h: two images of one size compared pixel by pixel: how they differ, and the verdict. */
#ifndef RAYTRA_PIXDIFF_H
#define RAYTRA_PIXDIFF_H

#include "diffopt.h"
#include "image.h"
#include "imgfile.h"

int pixdiff_run(Image img[2], const ImgFileKind kind[2], const DiffOptions *o);

#endif
