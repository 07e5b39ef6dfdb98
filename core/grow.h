/* Growing arrays that are kept between calls (neighbour lists, per-particle scratch,
 * the moving boundary set). */
#ifndef FSI_GROW_H
#define FSI_GROW_H

#include <stdlib.h>

/* realloc(old, bytes), or old itself (still valid) with *failed set when memory runs
 * out, so that a set of arrays is grown in a row and checked once. */
static inline void *fsi_grow(void *old, size_t bytes, int *failed)
{
    void *grown = realloc(old, bytes);
    if (!grown) {
        *failed = 1;
        return old;
    }
    return grown;
}

/* The capacity to grow to for n items: a quarter more, so that a slowly growing count
 * (the moving boundary set, the pairs of a compressing flow) reallocates rarely. */
static inline size_t fsi_grown_capacity(size_t n)
{
    return n + n / 4 + 16;
}

#endif
