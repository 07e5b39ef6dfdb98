/* Rows of a per-particle array in a new order: row k becomes old row sorted[k]. The
 * main loop sorts the particles by cell (fluid_main.c) and everything that keeps a
 * row per particle (the particle arrays, an integrator's previous state) follows with
 * this one function. scratch holds n rows of width bytes. */
#ifndef FSI_PERMUTE_ROWS_H
#define FSI_PERMUTE_ROWS_H

#include <stddef.h>
#include <string.h>

static inline void fsi_permute_rows(void *a, const int *sorted, int n, size_t width,
                                    void *scratch)
{
    unsigned char *src = a, *dst = scratch;
    for (int k = 0; k < n; k++)
        memcpy(dst + (size_t)k * width, src + (size_t)sorted[k] * width, width);
    memcpy(a, scratch, (size_t)n * width);
}

#endif
