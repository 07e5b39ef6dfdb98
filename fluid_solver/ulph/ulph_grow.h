/* Growing the arrays that the ULPH lists keep between evaluations. */
#ifndef ULPH_GROW_H
#define ULPH_GROW_H

#include <stdlib.h>

/* realloc(old, bytes), or old itself (still valid) with *failed set when memory runs
 * out, so that a set of arrays is grown in a row and checked once. */
static inline void *ulph_grow(void *old, size_t bytes, int *failed)
{
    void *grown = realloc(old, bytes);
    if (!grown) {
        *failed = 1;
        return old;
    }
    return grown;
}

#endif
