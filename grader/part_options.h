/* part_options.h: which options each part's program takes, for the tools that run them. */
#ifndef RAYTRA_PART_OPTIONS_H
#define RAYTRA_PART_OPTIONS_H

#include "cli.h"

const CliOption *const *part_options_of(const char *part);

#endif
