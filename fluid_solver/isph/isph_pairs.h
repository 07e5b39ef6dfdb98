/* Every particle's neighbours within the support, one full row each (ISPH's corrected
 * operators and its Poisson equation take a row per particle, not each pair once as
 * neighbours/fluid_rows.h does), filtered from the Verlet candidates at every
 * evaluation, with the pair vector and the cubic B-spline's W and F = (dW/dr) / r. */
#ifndef ISPH_PAIRS_H
#define ISPH_PAIRS_H

#include <stdint.h>

#include "cubic_spline.h"
#include "fluid_particles.h"
#include "verlet_list.h"

typedef struct {
    int n;                  /* particles of the last build */
    int64_t *start;         /* n + 1: i's pairs are start[i] .. start[i+1]-1 */
    int32_t *j;
    double *xij;            /* x_j - x_i (nearest periodic image), FSI_DIM per pair [m] */
    double *w;              /* W(|x_ij|) [1/m^DIM] */
    double *f;              /* F = (dW/dr) / r <= 0: grad_i W_ij = -F x_ij [1/m^(DIM+2)] */
    int capacity;
    int64_t pair_capacity;
} isph_pairs;

void isph_pairs_init(isph_pairs *q);
void isph_pairs_free(isph_pairs *q);

/* The pairs of p from its candidates (list built for p's current particle set).
 * 0, or -1 when memory runs out. */
int isph_pairs_build(isph_pairs *q, const fluid_verlet *list, const cubic_spline_kernel *k,
                     const fluid_particles *p);

#endif
