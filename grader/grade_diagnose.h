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

int diagnose_choose(const double *psnr, int count, double reference);
void diagnose_scene(const Grading *g, const Submission *s, int k, const char *image);

#endif
