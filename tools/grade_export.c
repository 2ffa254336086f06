/* grade_export.c: the verdicts for other tools: JUnit XML, and Gradescope's results.json. */
#include "grade.h"

/* Writes the verdicts to path as JUnit XML; false (reported) when it cannot. */
bool export_junit(const Grading *g, const char *path)
{
    (void)g;
    return grade_fail("cannot write %s: JUnit XML is not written yet", path);
}

/* Writes Gradescope's results.json for the one submission of --self to path; false
 * (reported) when it cannot. */
bool export_gradescope(const Grading *g, const char *path)
{
    (void)g;
    return grade_fail("cannot write %s: results.json is not written yet", path);
}
