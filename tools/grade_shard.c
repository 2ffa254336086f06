/* grade_shard.c: a class graded in slices (--shard K/N), and the slices merged into one report. */
#include "grade.h"

/* Reads --shard K/N into g; false (reported) when it is not a valid one. */
bool shard_parse(Grading *g)
{
    return g->shard == NULL || grade_fail("--shard is not written yet");
}

/* Writes the results of this shard; false (reported) when it cannot. */
bool shard_write(const Grading *g)
{
    (void)g;
    return grade_fail("--shard is not written yet");
}

/* Runs grade merge: argv[0] is "merge". Returns the exit status. */
int shard_merge(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    grade_fail("merge is not written yet");
    return 2;
}
