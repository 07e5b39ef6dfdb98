/* The neighbour pairs of one evaluation of the WCSPH rates: the shared CSR pair list
 * (neighbours/fluid_pairs.h, with W of each pair, which the dummy walls read) built
 * from the Verlet candidates (neighbours/verlet_list.h), and per pair what the SPH sums
 * need: the vector x_IJ = x_J - x_I and the kernel's F = (dW/dr) / r (Wendland C2,
 * kernels/wendland_c2.h), so that grad_I W_IJ = F (x_I - x_J) = -F x_IJ.
 *
 * Rows hold the candidates now within the support 2h, in the candidates' order; an
 * idle wall's row is empty. Both passes (row lengths, then rows) are parallel over
 * particles, each writing only its own row: the same on any number of threads. */
#ifndef WCSPH_PAIRS_H
#define WCSPH_PAIRS_H

#include <stdint.h>

#include "fluid_pairs.h"
#include "fluid_particles.h"
#include "verlet_list.h"
#include "wendland_c2.h"

typedef struct {
    fluid_pairs pairs;  /* neighbour, W */
    double *f;          /* (dW/dr) / r per pair [1/m^(DIM+2)] */
    double *rel;        /* x_J - x_I per pair, FSI_DIM each [m] */
    int point_capacity;
    int64_t pair_capacity;
} wcsph_pairs;

void wcsph_pairs_init(wcsph_pairs *pl);
void wcsph_pairs_free(wcsph_pairs *pl);

/* The pairs of p within k's support from candidate lists that hold every such pair.
 * 0, or -1 when memory runs out or the list is not for p->n particles. */
int wcsph_pairs_update(wcsph_pairs *pl, const wendland_c2_kernel *k, const fluid_verlet *list,
                       const fluid_particles *p);

#endif
