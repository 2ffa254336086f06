/* grade_merge.h: grade merge: the shards of a class made one report. */
#ifndef RAYTRA_GRADE_MERGE_H
#define RAYTRA_GRADE_MERGE_H

int merge_main(int argc, char **argv);
char *merge_describe_difference(const char *a, const char *b);

#endif
