/* accel_options.c: the course's MODE, which part 1.4 adds, and the options of the part. */
#include "accel.h"
#include "shade.h"
#include "trace.h"

/* clang-format off */
const CliOption accel_options[] = {
    {.name = "mode", .kind = OPTION_INT, .metavar = "MODE",
     .help = "0: test every surface, each behind its box; 1: draw each surface's box; "
             "2: draw the BVH's leaf boxes; 3 (the default): the BVH",
     .fallback = 3, .min = 0, .max = 3, .argument = "MODE"},
    {0},
};
/* clang-format on */

const CliOption *const accel_part_options[] = {shade_options, trace_options, accel_options, NULL};

/* Returns the mode the command line asks for (the course's third argument, or --mode). */
AccelMode accel_mode(const Options *opts)
{
    return (AccelMode)cli_int(opts, "mode");
}
