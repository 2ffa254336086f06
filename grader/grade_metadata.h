/* grade_metadata.h: grade metadata: the times of Gradescope's submission_metadata.json. */
#ifndef RAYTRA_GRADE_METADATA_H
#define RAYTRA_GRADE_METADATA_H

int metadata_main(int argc, char **argv);

#endif
