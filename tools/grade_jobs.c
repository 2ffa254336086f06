/* grade_jobs.c: grading the submissions N at a time, each in a worker process of its own. */
#include "grade.h"

/* Grades every submission, --jobs at a time; false when interrupted or on trouble. */
bool jobs_grade_all(Grading *g)
{
    return submission_grade_all(g);
}
