/* baseline_none.c: the benchmark's baseline when Embree 3 is not installed: there is none. */
#include "baseline.h"

/* Tells whether the baseline was compiled in: no. */
bool baseline_available(void)
{
    return false;
}

/* Builds nothing. */
Baseline *baseline_build(const Scene *scene, BaselineQuality quality, double *build_ms)
{
    (void)scene, (void)quality;
    *build_ms = 0;
    return NULL;
}

/* Traces nothing. */
long baseline_trace(const Baseline *b, const BenchRay *rays, long begin, long end, bool shadow)
{
    (void)b, (void)rays, (void)begin, (void)end, (void)shadow;
    return 0;
}

/* Frees nothing. */
void baseline_free(Baseline *b)
{
    (void)b;
}
