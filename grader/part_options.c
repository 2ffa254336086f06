/* part_options.c: which options each part's program takes, from the tables the parts declare. */
#include "part_options.h"

#include <string.h>

#include "accel.h"
#include "montecarlo.h"
#include "refract.h"
#include "shade.h"
#include "trace.h"

/* Each part by its folder's name, and the tables of its own options (CliSpec.options). */
static const struct {
    const char *part;
    const CliOption *const *options;
} parts[] = {
    {"1.1-spheres-red", NULL},
    {"1.2-shading", shade_part_options},
    {"1.3-shadows-mirror", trace_part_options},
    {"1.4-bvh", accel_part_options},
    {"1.5-refraction", refract_part_options},
    {"1.6-monte-carlo", montecarlo_part_options},
};

/* Returns the tables of the options of part, by its folder's name or its number alone
 * ("1.4-bvh", "1.4", or a course's own "1.4-accel"), beyond those every part takes;
 * NULL for a part that has none of its own, or that is not known. */
const CliOption *const *part_options_of(const char *part)
{
    size_t number = strcspn(part, "-");
    for (size_t k = 0; k < sizeof parts / sizeof *parts; k++)
        if (strncmp(parts[k].part, part, number) == 0 && parts[k].part[number] == '-')
            return parts[k].options;
    return NULL;
}
