/* grade_diagnose.h: a failing image told the known mistake of its part it most resembles. */
#ifndef RAYTRA_GRADE_DIAGNOSE_H
#define RAYTRA_GRADE_DIAGNOSE_H

#include "grading.h"

/* The rule that names a mistake (grader/docs/diagnosis.md), in dB: the PSNR of the image to
 * the mistake's render at least DIAGNOSE_NEAR, DIAGNOSE_OVER_REFERENCE above its PSNR to the
 * reference, DIAGNOSE_OVER_NEXT above its PSNR to any other mistake's render; equal images
 * count as DIAGNOSE_EQUAL. */
#define DIAGNOSE_NEAR 30.0
#define DIAGNOSE_OVER_REFERENCE 6.0
#define DIAGNOSE_OVER_NEXT 3.0
#define DIAGNOSE_EQUAL 99.0
/* When no render is that near: the image differs from the reference where one mistake's
 * render does, its differences summed over squares of DIAGNOSE_BLOCK pixels having a cosine
 * of at least DIAGNOSE_ALIKE with the mistake's, DIAGNOSE_ALIKE_OVER above any other's. */
#define DIAGNOSE_BLOCK 8
#define DIAGNOSE_ALIKE 0.8
#define DIAGNOSE_ALIKE_OVER 0.2

int diagnose_choose(const double *psnr, int count, double reference);
int diagnose_choose_alike(const double *like, int count);
void diagnose_scene(const Grading *g, const Submission *s, int k, const char *image);

#endif
