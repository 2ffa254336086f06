/* shade_options.c: the option part 1.2 adds to the command line, and the options of the part. */
#include "shade.h"

/* clang-format off */
const CliOption shade_options[] = {
    {.name = "two-sided",
     .help = "shade the backs of triangles and planes with their own material, not lit yellow"},
    {0},
};
/* clang-format on */

const CliOption *const shade_part_options[] = {shade_options, NULL};
