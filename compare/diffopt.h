/* diffopt.h: what imgdiff's command line asks for, and the exit statuses imgdiff answers with. */
#ifndef RAYTRA_DIFFOPT_H
#define RAYTRA_DIFFOPT_H

#include <stdbool.h>

#include "statstandard.h"

/* imgdiff's exit statuses: the images match, they do not, or trouble. */
enum { EXIT_MATCH = 0, EXIT_DIFFER = 1, EXIT_TROUBLE = 2 };

/* What the command line asks for. */
typedef struct {
    const char *paths[2], *diff_path;    /* the images; --diff's heat map, or NULL */
    const char *thumb_path, *diff_thumb; /* --thumb's and --diff-thumb's files, or NULL */
    double threshold; /* a pixel differs when its largest channel difference exceeds this */
    double allow;     /* the fraction of the pixels that may differ */
    double scale;     /* the difference shown white in the heat map; 0: the largest found */
    bool quiet, help, machine; /* machine: figures as NAME VALUE lines, for grader/grade */
    bool cover; /* --cover: a pixel differs when A is drawn there and B is not */
    StatStandard standard;     /* a Monte Carlo render's: "good" or "ok" (statstandard.h) */
} DiffOptions;

#endif
