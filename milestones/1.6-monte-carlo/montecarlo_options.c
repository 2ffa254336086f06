/* montecarlo_options.c: the course's P and S, and the sampling options, which part 1.6 adds. */
#include "montecarlo.h"
#include "shade.h"

/* clang-format off */
const CliOption montecarlo_options[] = {
    {.name = "samples", .kind = OPTION_INT, .metavar = "P",
     .help = "trace P x P primary rays per pixel, one in each of P x P sub-squares "
             "(default 1, through the pixel's centre; at most 64)",
     .fallback = 1, .min = 1, .max = MONTECARLO_MAX_SIDE, .argument = "P"},
    {.name = "light-samples", .kind = OPTION_INT, .metavar = "S",
     .help = "trace S x S shadow rays to every area light at every hit (default 1; at most 64)",
     .fallback = 1, .min = 1, .max = MONTECARLO_MAX_SIDE, .argument = "S"},
    {.name = "seed", .kind = OPTION_INT, .metavar = "N",
     .help = "pick other random numbers; the same seed always gives the same image (default 0)",
     .min = 0, .max = 2147483647},
    {.name = "sampling", .kind = OPTION_TEXT, .metavar = "NAME",
     .help = "how sample points are placed: random (independent), jittered (one in each "
             "sub-square, pixel and light apart) or correlated (jittered, and with S = 1 the "
             "shadow rays of a pixel's P x P rays cover the light evenly; the default)"},
    {0},
};
/* clang-format on */

/* Part 1.6 keeps the options of 1.2, 1.3 and 1.5; it always uses the BVH, so not MODE. */
const CliOption *const montecarlo_part_options[] = {shade_options, trace_options,
                                                    refract_options, montecarlo_options, NULL};
