/* splitmix64: a fixed-seed sequence of uniform numbers in [0, 1) for the tests (each
 * test keeps its own state, so its sequence does not depend on the others). */
#ifndef FSI_UNIT_RANDOM_H
#define FSI_UNIT_RANDOM_H

#include <stdint.h>

static inline double unit_uniform(uint64_t *state)
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return (double)(z >> 11) / 9007199254740992.0;
}

#endif
