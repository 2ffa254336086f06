/* statverdict.h: the verdict on a render compared by statistics, with the test that decides it. */
#ifndef RAYTRA_STATVERDICT_H
#define RAYTRA_STATVERDICT_H

#include <stdbool.h>
#include <stddef.h>

#include "mcref.h"
#include "statcompare.h"

const BlockTest *statverdict_worst(const StatDiff *d);
bool statverdict_decide(const StatDiff *d, const McRef *ref, int width, int height, char *test,
                        char *text, size_t size);
void statverdict_block_text(const BlockTest *t, int width, int height, char *text, size_t size);
void statverdict_square_text(const NoiseTest *n, int width, int height, char *text, size_t size);

#endif
