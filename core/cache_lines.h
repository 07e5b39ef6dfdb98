/* Arrays that start on a cache line, for per-particle records sized in whole lines (a
 * pair loop then touches one or two lines per neighbour). */
#ifndef FSI_CACHE_LINES_H
#define FSI_CACHE_LINES_H

#include <stdlib.h>

#define FSI_CACHE_LINE 64

/* n doubles on a 64-byte boundary (free with free()), or NULL. */
static inline double *fsi_alloc_lines(size_t n)
{
    const size_t bytes = (n * sizeof(double) + FSI_CACHE_LINE - 1) / FSI_CACHE_LINE *
                         FSI_CACHE_LINE;
    return aligned_alloc(FSI_CACHE_LINE, bytes > 0 ? bytes : FSI_CACHE_LINE);
}

#endif
