/* variants.c: part 1.6 with one student function replaced, right or wrong, each compiled alone
 * (-DVARIANT_name) and linked in its place, to show what the statistical grading passes and
 * fails (tests/mc-variants/run.sh). */
#include <math.h>
#include <stdint.h>

#include "area.h"
#include "montecarlo.h"
#include "shade.h"
#include "strata.h"

#ifdef VARIANT_rv_first
void __wrap_strata_point(Sampling sampling, Rng *rng, int k, int n, double *u, double *v);

/* Right, as a starter may be solved: rv drawn before ru, so every point differs from
 * raytra's, and is as good. */
void __wrap_strata_point(Sampling sampling, Rng *rng, int k, int n, double *u, double *v)
{
    double rv = rng_uniform(rng), ru = rng_uniform(rng);
    *u = sampling == SAMPLING_RANDOM ? ru : (k % n + ru) / n;
    *v = sampling == SAMPLING_RANDOM ? rv : (k / n + rv) / n;
}
#endif

#ifdef VARIANT_own_rng
/* Right, as a student may write it: a random generator of one's own (xorshift64*, one
 * state a thread), not raytra's PCG32 streams, for the pixel's points and the light's. */
static _Thread_local uint64_t state;

/* Returns a uniform number in [0, 1) from the thread's xorshift64* generator. */
static double own_uniform(void)
{
    if (state == 0)
        state = 0x9e3779b97f4a7c15u ^ (uint64_t)(uintptr_t)&state;
    state ^= state >> 12;
    state ^= state << 25;
    state ^= state >> 27;
    return (double)((state * 0x2545f4914f6cdd1du) >> 11) / 9007199254740992.0;
}

/* Jittered points of the pixel, from one's own numbers. */
void montecarlo_point(const MonteCarlo *mc, Rng *rng, int i, int j, int k, double *x, double *y)
{
    (void)rng;
    int n = mc->pixel_side;
    *x = n == 1 ? i + 0.5 : i + (k % n + own_uniform()) / n;
    *y = n == 1 ? j + 0.5 : j + (k / n + own_uniform()) / n;
}

/* Stratified points of the light (in the pixel's stratum pi(k) when S = 1), from one's own
 * numbers. */
void montecarlo_light_point(const MonteCarlo *mc, const Sample *sample, int q, double *ru,
                            double *rv)
{
    int n = mc->light_side, stratum = q;
    if (n == 1 && sample->strata_side > 1)
        n = sample->strata_side, stratum = sample->stratum;
    *ru = (stratum % n + own_uniform()) / n;
    *rv = (stratum / n + own_uniform()) / n;
}
#endif

#ifdef VARIANT_no_cosine
Color __wrap_shade_blinn_phong(const Material *m, Vec3 n, Vec3 v, const Incident *in);

/* Wrong: each light sample's diffuse light not scaled by the cosine n.l ("scaled, as
 * before, by the cosine"). In raytra the cosine is part 1.2's Blinn-Phong, which every
 * light sample goes through: this wraps it (the scenes it is tried on have area lights only). */
Color __wrap_shade_blinn_phong(const Material *m, Vec3 n, Vec3 v, const Incident *in)
{
    BlinnPhong t = shade_blinn_phong_terms(m, n, v, in);
    double cosine = vec3_dot(n, in->dir);
    if (cosine > 0)
        t.diffuse = color_scale(t.diffuse, 1 / cosine);
    return color_add(t.diffuse, t.specular);
}
#endif

#ifdef VARIANT_one_over_s
Incident __real_area_incident(const Light *light, Vec3 at, Vec3 point, int count, bool falls_off);
Incident __wrap_area_incident(const Light *light, Vec3 at, Vec3 point, int count, bool falls_off);

/* Wrong: each of the S^2 light samples weighted 1/S instead of 1/S^2. */
Incident __wrap_area_incident(const Light *light, Vec3 at, Vec3 point, int count, bool falls_off)
{
    return __real_area_incident(light, at, point, (int)lround(sqrt(count)), falls_off);
}
#endif

#ifdef VARIANT_flipped
Incident __real_area_incident(const Light *light, Vec3 at, Vec3 point, int count, bool falls_off);
Incident __wrap_area_incident(const Light *light, Vec3 at, Vec3 point, int count, bool falls_off);

/* Wrong: the light's normal turned round, so that it shines on the side it should not. */
Incident __wrap_area_incident(const Light *light, Vec3 at, Vec3 point, int count, bool falls_off)
{
    Light flipped = *light;
    flipped.direction = vec3_neg(light->direction);
    return __real_area_incident(&flipped, at, point, count, falls_off);
}
#endif

#ifdef VARIANT_no_falloff
Incident __real_area_incident(const Light *light, Vec3 at, Vec3 point, int count, bool falls_off);
Incident __wrap_area_incident(const Light *light, Vec3 at, Vec3 point, int count, bool falls_off);

/* Wrong: the Fall 2016 convention's 1/r^2 falloff left out for area lights. */
Incident __wrap_area_incident(const Light *light, Vec3 at, Vec3 point, int count, bool falls_off)
{
    (void)falls_off;
    return __real_area_incident(light, at, point, count, false);
}
#endif

#ifdef VARIANT_not_stratified
/* Wrong: the pixel's P x P points uniform over the whole pixel, not one in each sub-square. */
void montecarlo_point(const MonteCarlo *mc, Rng *rng, int i, int j, int k, double *x, double *y)
{
    double du = 0.5, dv = 0.5;
    if (mc->pixel_side > 1)
        strata_point(SAMPLING_RANDOM, rng, k, mc->pixel_side, &du, &dv);
    *x = i + du;
    *y = j + dv;
}
#endif

#ifdef VARIANT_half_pixel
/* Wrong: the jitter added to the pixel's centre, not to its corner: every ray half a pixel
 * off, the pixel's width spread twice over (half of it in the next pixel). */
void montecarlo_point(const MonteCarlo *mc, Rng *rng, int i, int j, int k, double *x, double *y)
{
    *x = i + 0.5;
    *y = j + 0.5;
    if (mc->pixel_side > 1) {
        double du, dv;
        strata_point(mc->sampling, rng, k, mc->pixel_side, &du, &dv);
        *x += du;
        *y += dv;
    }
}
#endif
