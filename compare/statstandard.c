/* statstandard.c: the course's two standards of a soft shadow, by their names. */
#include "statstandard.h"

#include <string.h>

/* Returns the standard's name, as --standard takes it. */
const char *statstandard_name(StatStandard standard)
{
    return standard == STATDIFF_OK ? "ok" : "good";
}

/* Sets *standard from its name, "good" or "ok"; false when it is neither. */
bool statstandard_from_name(const char *name, StatStandard *standard)
{
    if (strcmp(name, "good") != 0 && strcmp(name, "ok") != 0)
        return false;
    *standard = strcmp(name, "ok") == 0 ? STATDIFF_OK : STATDIFF_GOOD;
    return true;
}
