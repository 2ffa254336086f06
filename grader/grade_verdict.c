/* grade_verdict.c: what became of a scene: each verdict's name and column; a verdict set with its reason. */
#include "grade_verdict.h"

#include <stdarg.h>

/* Each verdict's name and column; in the order of Verdict. */
const VerdictInfo verdict_info[VERDICT_COUNT] = {
    {"PASS", TALLY_PASS},         {"FAIL", TALLY_FAIL},       {"WRONG SIZE", TALLY_FAIL},
    {"LINK", TALLY_FAIL},         {"UNREADABLE", TALLY_FAIL}, {"MISSING", TALLY_MISSING},
    {"ERROR", TALLY_ERROR},       {"CRASHED", TALLY_ERROR},   {"TIMEOUT", TALLY_ERROR},
    {"OUT OF MEMORY", TALLY_ERROR}, {"BUILD FAILED", TALLY_ERROR},
};

/* Sets the verdict of res and its reason, made as printf makes it. */
void verdict_set(SceneResult *res, Verdict v, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(res->message, sizeof res->message, fmt, ap);
    va_end(ap);
    res->verdict = v;
}
