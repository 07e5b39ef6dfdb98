/* A small deterministic random number generator for unit tests (splitmix64): the same
 * sequence on every platform for a given seed in rng_state. */
#ifndef FSI_UNIT_RANDOM_H
#define FSI_UNIT_RANDOM_H

#include <stdint.h>

static uint64_t rng_state;

/* Uniform in [0, 1). */
static inline double uniform(void)
{
    uint64_t z = (rng_state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return (double)(z >> 11) / 9007199254740992.0;
}

#endif
