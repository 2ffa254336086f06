/* baseline_tinybvh_none.c: the tinybvh baselines when tinybvh's header is not there: none. */
#include "baseline_tinybvh.h"

/* Tells whether the baselines were compiled in: no. */
bool tiny_available(void)
{
    return false;
}

/* Builds nothing. */
TinyBaseline *tiny_build(const Scene *scene, TinyLayout layout, double *build_ms)
{
    (void)scene, (void)layout;
    *build_ms = 0;
    return NULL;
}

/* Traces nothing. */
long tiny_trace(const TinyBaseline *b, const BenchRay *rays, long begin, long end, bool shadow)
{
    (void)b, (void)rays, (void)begin, (void)end, (void)shadow;
    return 0;
}

/* Frees nothing. */
void tiny_free(TinyBaseline *b)
{
    (void)b;
}
