/* rng.h: PCG32, a small random number generator that gives the same numbers on every machine. */
#ifndef RAYTRA_RNG_H
#define RAYTRA_RNG_H

#include <stdint.h>

/* One stream of O'Neill's PCG32 (pcg-random.org): a 64-bit linear congruential state,
 * of which each step outputs a permuted 32 bits. Streams of different inc never meet. */
typedef struct {
    uint64_t state;
    uint64_t inc; /* odd: which of 2^63 streams */
} Rng;

uint64_t rng_hash(uint64_t x);
Rng rng_make(uint64_t seed, uint64_t stream);
uint32_t rng_next(Rng *rng);
double rng_uniform(Rng *rng);
uint32_t rng_below(Rng *rng, uint32_t n);

#endif
