/* trace_options.c: the options part 1.3 adds to the command line, and the options of the part. */
#include "shade.h"
#include "trace.h"

/* clang-format off */
const CliOption trace_options[] = {
    {.name = "max-depth", .kind = OPTION_INT, .metavar = "N",
     .help = "follow at most N mirror reflections along a path (default 20; 0: none)",
     .fallback = 20, .min = 0, .max = 1000},
    {.name = "ray-offset", .kind = OPTION_NUMBER, .metavar = "F",
     .help = "start shadow and reflected rays F times the size of the hit point's "
             "coordinates off the surface (default 2^-32); 0 shows shadow acne",
     .fallback = 0x1p-32, .min = 0, .max = 1},
    {0},
};
/* clang-format on */

const CliOption *const trace_part_options[] = {shade_options, trace_options, NULL};
