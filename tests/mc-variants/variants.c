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

#if defined VARIANT_xorshift || defined VARIANT_drand48
#include "rng.h"
double __wrap_rng_uniform(Rng *rng);

/* Right, as a student may write it: every sample's numbers from a generator of one's own,
 * xorshift64* or drand48's 48-bit linear congruence, seeded once from the sample's
 * stream (its state hashed on the first draw, marked by an even inc). */
double __wrap_rng_uniform(Rng *rng)
{
    if (rng->inc & 1) {
        rng->state = rng_hash(rng->state ^ rng->inc) | 1;
        rng->inc = 0;
    }
#ifdef VARIANT_xorshift
    uint64_t x = rng->state;
    x ^= x >> 12;
    x ^= x << 25;
    x ^= x >> 27;
    rng->state = x;
    return (double)((x * 0x2545f4914f6cdd1du) >> 11) / 9007199254740992.0;
#else
    rng->state = (0x5deece66du * rng->state + 0xb) & ((1ull << 48) - 1);
    return (double)rng->state / 281474976710656.0;
#endif
}
#endif

#ifdef VARIANT_transposed
void __wrap_strata_point(Sampling sampling, Rng *rng, int k, int n, double *u, double *v);

/* Right: the strata counted column by column, not row by row: another order, as good. */
void __wrap_strata_point(Sampling sampling, Rng *rng, int k, int n, double *u, double *v)
{
    double ru = rng_uniform(rng), rv = rng_uniform(rng);
    *u = sampling == SAMPLING_RANDOM ? ru : (k / n + ru) / n;
    *v = sampling == SAMPLING_RANDOM ? rv : (k % n + rv) / n;
}
#endif

#ifdef VARIANT_shift
void __wrap_strata_shuffle(Rng *rng, int *perm, int count);

/* Right: the light's strata correlated with the pixel's by a random cyclic shift, not a
 * random permutation: sub-pixel k takes light stratum (k + r) mod P^2. Unbiased, since
 * each ray's light point is still uniform over the light. */
void __wrap_strata_shuffle(Rng *rng, int *perm, int count)
{
    int r = (int)rng_below(rng, (uint32_t)count);
    for (int k = 0; k < count; k++)
        perm[k] = (k + r) % count;
}
#endif

#ifdef VARIANT_random_light
/* Right by the "ok" standard: every shadow ray to a uniform random point of the whole
 * light, not stratified, not correlated with the pixel's strata. */
void montecarlo_light_point(const MonteCarlo *mc, const Sample *sample, int q, double *ru,
                            double *rv)
{
    (void)mc, (void)q;
    *ru = rng_uniform(sample->rng);
    *rv = rng_uniform(sample->rng);
}
#endif

#if defined VARIANT_bright_2 || defined VARIANT_bright_1
Color __real_montecarlo_pixel(const MonteCarlo *mc, int i, int j, RayStats *stats);
Color __wrap_montecarlo_pixel(const MonteCarlo *mc, int i, int j, RayStats *stats);

/* Wrong: every pixel 2 % (1 %) too bright, as a light's power slightly off would make it. */
Color __wrap_montecarlo_pixel(const MonteCarlo *mc, int i, int j, RayStats *stats)
{
#ifdef VARIANT_bright_2
    return color_scale(__real_montecarlo_pixel(mc, i, j, stats), 1.02);
#else
    return color_scale(__real_montecarlo_pixel(mc, i, j, stats), 1.01);
#endif
}
#endif

#ifdef VARIANT_denoise
Color __real_montecarlo_pixel(const MonteCarlo *mc, int i, int j, RayStats *stats);
Color __wrap_montecarlo_pixel(const MonteCarlo *mc, int i, int j, RayStats *stats);

/* Wrong: a denoiser, the pixel averaged with its four neighbours' estimates (a cross of
 * five pixels, clamped at the image's edges). */
Color __wrap_montecarlo_pixel(const MonteCarlo *mc, int i, int j, RayStats *stats)
{
    int nx = mc->camera.nx, ny = mc->camera.ny;
    int di[] = {0, 1, -1, 0, 0}, dj[] = {0, 0, 0, 1, -1};
    Color sum = color(0, 0, 0);
    for (int k = 0; k < 5; k++) {
        int x = i + di[k] < 0 ? 0 : i + di[k] >= nx ? nx - 1 : i + di[k];
        int y = j + dj[k] < 0 ? 0 : j + dj[k] >= ny ? ny - 1 : j + dj[k];
        sum = color_add(sum, __real_montecarlo_pixel(mc, x, y, stats));
    }
    return color_scale(sum, 0.2);
}
#endif

#ifdef VARIANT_checker
Color __real_montecarlo_pixel(const MonteCarlo *mc, int i, int j, RayStats *stats);
Color __wrap_montecarlo_pixel(const MonteCarlo *mc, int i, int j, RayStats *stats);

/* Wrong where the references see no noise: the sky (where the camera ray through the
 * pixel's centre meets nothing) 0.5 brighter in every other pixel, a checkerboard. */
Color __wrap_montecarlo_pixel(const MonteCarlo *mc, int i, int j, RayStats *stats)
{
    Color c = __real_montecarlo_pixel(mc, i, j, stats);
    Probe probe;
    montecarlo_probe(mc, i, j, &probe);
    if (!probe.hit && (i + j) % 2 == 0)
        c = color_add(c, color(0.5, 0.5, 0.5));
    return c;
}
#endif

#ifdef VARIANT_more_samples
bool __real_montecarlo_init(MonteCarlo *mc, const Scene *scene, Surfaces surfaces,
                            const Options *opts);
bool __wrap_montecarlo_init(MonteCarlo *mc, const Scene *scene, Surfaces surfaces,
                            const Options *opts);

/* Wrong: more samples than asked, four times as many: 2P x 2P rays a pixel, or at P = 1
 * (one ray through the centre) 2S x 2S shadow rays. */
bool __wrap_montecarlo_init(MonteCarlo *mc, const Scene *scene, Surfaces surfaces,
                            const Options *opts)
{
    if (!__real_montecarlo_init(mc, scene, surfaces, opts))
        return false;
    if (mc->pixel_side == 1)
        mc->light_side *= 2;
    else
        mc->pixel_side *= 2;
    return true;
}
#endif

#ifdef VARIANT_no_jitter
/* Wrong: each of the P x P rays through the centre of its sub-square, not a random point
 * of it: regular supersampling, which aliases. */
void montecarlo_point(const MonteCarlo *mc, Rng *rng, int i, int j, int k, double *x, double *y)
{
    (void)rng;
    int n = mc->pixel_side;
    *x = i + (k % n + 0.5) / n;
    *y = j + (k / n + 0.5) / n;
}
#endif

#ifdef VARIANT_hard_shadow
/* Wrong: each light sample at the centre of its stratum, not a random point of it: at
 * S = 1, without correlation, the light's centre alone, a hard shadow. */
void montecarlo_light_point(const MonteCarlo *mc, const Sample *sample, int q, double *ru,
                            double *rv)
{
    int n = mc->light_side, stratum = q;
    if (n == 1 && sample->strata_side > 1)
        n = sample->strata_side, stratum = sample->stratum;
    *ru = (stratum % n + 0.5) / n;
    *rv = (stratum / n + 0.5) / n;
}
#endif

#ifdef VARIANT_same_offsets
#include "rng.h"

/* Wrong: the light's points drawn from numbers made afresh from the seed and q alone, the
 * same for every pixel: each pixel's shadow is sampled at the same points, so the noise of
 * neighbouring pixels is one, and a soft shadow turns to bands. */
void montecarlo_light_point(const MonteCarlo *mc, const Sample *sample, int q, double *ru,
                            double *rv)
{
    Rng same = rng_make(mc->seed, (uint64_t)q);
    if (mc->light_side == 1 && sample->strata_side > 1)
        strata_point(SAMPLING_JITTERED, &same, sample->stratum, sample->strata_side, ru, rv);
    else
        strata_point(mc->sampling, &same, q, mc->light_side, ru, rv);
}
#endif

#ifdef VARIANT_wide_filter
/* Wrong: the pixel's points spread over a square 2 pixels wide round its centre, a box
 * filter twice the pixel: the image is blurred, and noisier than raytra's where it is. */
void montecarlo_point(const MonteCarlo *mc, Rng *rng, int i, int j, int k, double *x, double *y)
{
    *x = i + 0.5;
    *y = j + 0.5;
    if (mc->pixel_side > 1) {
        double du, dv;
        strata_point(mc->sampling, rng, k, mc->pixel_side, &du, &dv);
        *x = i + 0.5 + 2 * (du - 0.5);
        *y = j + 0.5 + 2 * (dv - 0.5);
    }
}
#endif

#if defined VARIANT_multi_jitter || defined VARIANT_latin_hypercube
/* Fills perm with a permutation of 0 to n - 1 of pixel (i, j)'s own, the number-th of
 * its kind: the same for every ray of the pixel, which shares it. */
static void pixel_permutation(const MonteCarlo *mc, int i, int j, int number, int *perm, int n)
{
    uint64_t key =
        rng_hash(mc->seed ^ 0x6d756c74696a6974u) ^ ((uint64_t)(uint32_t)j << 32 | (uint32_t)i);
    Rng rng = rng_make(rng_hash(key), (uint64_t)number + 1);
    strata_shuffle(&rng, perm, n);
}
#endif

#ifdef VARIANT_multi_jitter
/* Right: multi-jittered points (Chiu, Shirley and Wang 1994): one in each of the P x P
 * sub-squares, and one in each of the P^2 columns and rows of width 1/P^2 (n-rooks):
 * sub-square (a, b) takes fine column a P + sigma_a(b) and fine row b P + tau_b(a),
 * sigma_a and tau_b the pixel's own permutations. Less noisy than jitter, unbiased. */
void montecarlo_point(const MonteCarlo *mc, Rng *rng, int i, int j, int k, double *x, double *y)
{
    int n = mc->pixel_side, a = k % n, b = k / n;
    *x = i + 0.5;
    *y = j + 0.5;
    if (n == 1)
        return;
    int sigma[MONTECARLO_MAX_SIDE], tau[MONTECARLO_MAX_SIDE];
    pixel_permutation(mc, i, j, a, sigma, n);
    pixel_permutation(mc, i, j, n + b, tau, n);
    *x = i + (a + (sigma[b] + rng_uniform(rng)) / n) / n;
    *y = j + (b + (tau[a] + rng_uniform(rng)) / n) / n;
}
#endif

#ifdef VARIANT_latin_hypercube
/* Right: Latin hypercube points in the pixel: ray k in fine row k of P^2 and in fine
 * column pi(k), pi the pixel's own permutation (n-rooks, without the sub-squares).
 * Each point uniform over the pixel: unbiased. */
void montecarlo_point(const MonteCarlo *mc, Rng *rng, int i, int j, int k, double *x, double *y)
{
    int n = mc->pixel_side * mc->pixel_side;
    *x = i + 0.5;
    *y = j + 0.5;
    if (n == 1)
        return;
    int pi[MONTECARLO_MAX_SIDE * MONTECARLO_MAX_SIDE];
    pixel_permutation(mc, i, j, 0, pi, n);
    *x = i + (pi[k] + rng_uniform(rng)) / n;
    *y = j + (k + rng_uniform(rng)) / n;
}
#endif

#ifdef VARIANT_hashed
#include "rng.h"
double __wrap_rng_uniform(Rng *rng);

/* Right: every random number a hash of the sample's stream and a counter (SplitMix64's
 * finaliser, a counter-based generator), not the steps of a generator's state. */
double __wrap_rng_uniform(Rng *rng)
{
    uint64_t z = rng->inc ^ (rng->state += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    z ^= z >> 31;
    return (double)(z >> 11) / 9007199254740992.0;
}
#endif

#if defined VARIANT_light_1pct || defined VARIANT_light_small
Incident __real_area_incident(const Light *light, Vec3 at, Vec3 point, int count, bool falls_off);
Incident __wrap_area_incident(const Light *light, Vec3 at, Vec3 point, int count, bool falls_off);

/* Wrong: the area light 1 % too bright (its colour 1.01 times the scene's); or, for the
 * light's size, its square 0.9 of its side (the points on it drawn from the smaller
 * square about its centre: a penumbra a tenth narrower, as bright in all). */
Incident __wrap_area_incident(const Light *light, Vec3 at, Vec3 point, int count, bool falls_off)
{
    Light changed = *light;
#ifdef VARIANT_light_1pct
    changed.color = color_scale(light->color, 1.01);
#else
    at = vec3_add(light->position, vec3_scale(vec3_sub(at, light->position), 0.9));
#endif
    return __real_area_incident(&changed, at, point, count, falls_off);
}
#endif
