/* refract_options.c: the options part 1.5 adds to the command line, and the options of the part. */
#include "accel.h"
#include "refract.h"
#include "shade.h"
#include "trace.h"

/* clang-format off */
const CliOption refract_options[] = {
    {.name = "fresnel", .kind = OPTION_TEXT, .metavar = "MODEL",
     .help = "how much light glass reflects: schlick (Schlick's approximation, the default) "
             "or exact (the Fresnel equations for unpolarised light)"},
    {.name = "min-weight", .kind = OPTION_NUMBER, .metavar = "F",
     .help = "do not follow mirror, reflected or refracted rays that make up less than F of "
             "their pixel (default 2^-16, far below a PNG's steps; 0: only --max-depth "
             "stops them)",
     .fallback = 0x1p-16, .min = 0, .max = 1},
    {0},
};
/* clang-format on */

/* Part 1.5 takes 1.4's MODE too: its glass is found through the boxes of every mode. */
const CliOption *const refract_part_options[] = {shade_options, trace_options, accel_options,
                                                 refract_options, NULL};
