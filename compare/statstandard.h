/* statstandard.h: the course's two standards of a soft shadow, and their names. */
#ifndef RAYTRA_STATSTANDARD_H
#define RAYTRA_STATSTANDARD_H

#include <stdbool.h>

/* The course's two standards of a soft shadow: "good", stratified or correlated light
 * samples (raytra's); "ok", random points on the light. */
typedef enum { STATDIFF_GOOD, STATDIFF_OK } StatStandard;

const char *statstandard_name(StatStandard standard);
bool statstandard_from_name(const char *name, StatStandard *standard);

#endif
