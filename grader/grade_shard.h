/* grade_shard.h: a class in slices (--shard K/N), and shard.txt. */
#ifndef RAYTRA_GRADE_SHARD_H
#define RAYTRA_GRADE_SHARD_H

#include <stdbool.h>

#include "grading.h"

bool shard_parse(Grading *g);
void shard_select(Grading *g);
bool shard_write(const Grading *g);
bool shard_read(Grading *g, const char *folder);
bool shard_read_class(Grading *g, const char *out);
char *shard_format_heading(const Grading *g);

#endif
