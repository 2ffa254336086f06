/* array.h: growing the plain C arrays the scene and mesh readers fill. */
#ifndef RAYTRA_ARRAY_H
#define RAYTRA_ARRAY_H

#include <stdbool.h>
#include <stddef.h>

/* No array raytra reads from a file grows beyond this many items. */
#define ARRAY_MAX_ITEMS 50000000

bool array_grow(void *items, int *capacity, int count, size_t item_size);

#endif
