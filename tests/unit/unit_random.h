/* splitmix64: a fixed-seed sequence of uniform numbers in [0, 1) for the tests, the same
 * on every platform. unit_uniform keeps its state where the caller says (a test whose
 * sequence must not depend on the others'); uniform() is the one sequence of a test
 * file, seeded through rng_state. */
#ifndef FSI_UNIT_RANDOM_H
#define FSI_UNIT_RANDOM_H

#include <stdint.h>

static inline double unit_uniform(uint64_t *state)
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return (double)(z >> 11) * 0x1.0p-53;
}

static uint64_t rng_state;

static inline double uniform(void)
{
    return unit_uniform(&rng_state);
}

#endif
