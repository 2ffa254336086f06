/* rng.c: PCG32 (O'Neill 2014, pcg32_random_r of its reference C code), and uniforms. */
#include "rng.h"

/* Returns x scrambled: the finaliser of SplitMix64 (Steele et al. 2014), which turns
 * neighbouring numbers (pixel indices, seeds) into unrelated 64-bit seeds. */
uint64_t rng_hash(uint64_t x)
{
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

/* Returns the generator of stream number stream, started from seed, as pcg32_srandom_r. */
Rng rng_make(uint64_t seed, uint64_t stream)
{
    Rng rng = {.state = 0, .inc = (stream << 1) | 1};
    rng_next(&rng);
    rng.state += seed;
    rng_next(&rng);
    return rng;
}

/* Returns the next 32 random bits: one step of the LCG, its high bits xor-shifted and
 * rotated by an amount the top bits choose (the "XSH RR" output function). */
uint32_t rng_next(Rng *rng)
{
    uint64_t old = rng->state;
    rng->state = old * 6364136223846793005ULL + rng->inc;
    uint32_t xorshifted = (uint32_t)(((old >> 18) ^ old) >> 27);
    uint32_t rot = (uint32_t)(old >> 59);
    return (xorshifted >> rot) | (xorshifted << ((32 - rot) & 31));
}

/* Returns a number uniform in [0, 1): 32 random bits over 2^32, never 1. */
double rng_uniform(Rng *rng)
{
    return rng_next(rng) * 0x1p-32;
}

/* Returns a whole number uniform in [0, n), n > 0, without modulo bias: draws that
 * fall in the incomplete last copy of [0, n) are drawn again. */
uint32_t rng_below(Rng *rng, uint32_t n)
{
    uint32_t threshold = (uint32_t)(-n) % n; /* 2^32 mod n */
    for (;;) {
        uint32_t r = rng_next(rng);
        if (r >= threshold)
            return r % n;
    }
}
