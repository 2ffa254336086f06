/* array.c: doubling growth for arrays of any item type. */
#include "array.h"

#include <stdlib.h>
#include <string.h>

/* Makes room for item number count in *(void **)items, doubling its capacity
 * when full; false when memory runs out or ARRAY_MAX_ITEMS is reached. */
bool array_grow(void *items, int *capacity, int count, size_t item_size)
{
    if (count < *capacity)
        return true;
    if (count >= ARRAY_MAX_ITEMS)
        return false;
    int larger = *capacity > 0 ? 2 * *capacity : 16;
    if (larger > ARRAY_MAX_ITEMS)
        larger = ARRAY_MAX_ITEMS;
    void *old;
    memcpy(&old, items, sizeof old);
    void *grown = realloc(old, (size_t)larger * item_size);
    if (grown == NULL)
        return false;
    memcpy(items, &grown, sizeof grown);
    *capacity = larger;
    return true;
}
