/* statexact.h: the exact test of the pixels that every render of the reference saw alike. */
#ifndef RAYTRA_STATEXACT_H
#define RAYTRA_STATEXACT_H

#include <stdbool.h>

#include "mcref.h"

/* The error rate of the exact test of the pixels the references saw without noise: with
 * the bias test's (STATDIFF_ALPHA, statbias.h), the chance that a correct render of one
 * scene fails (docs/grading.md measures it). */
#define STATDIFF_ALPHA_EXACT 0.00001

double statexact_tolerance(bool codes, double m);
bool statexact_near_noise(const McRef *ref, bool codes, int *near);
long statexact_fringe_limit(long fringe_channels);

#endif
