/* The non-local differential operators of ULPH (000 §2.1.2, Eqs. 8-15), in the
 * current configuration, over the neighbours of each particle within the kernel's
 * support.
 *
 * With x_IJ = x_J - x_I, A(f) = f_J - f_I (000, below Eq. 10), w the kernel
 * (gaussian_kernel.h) and V_J the neighbour's volume:
 *
 *     M_I      = sum_J w(x_IJ) V_J x_IJ (x) x_IJ                (000 Eq. 15, from Eq. 11)
 *     grad f_I = sum_J w(x_IJ) V_J A(f) M_I^-1 x_IJ             (000 Eq. 13, from Eq. 9)
 *     L_I      = sum_J w(x_IJ) V_J A(u) (x) (M_I^-1 x_IJ)       (000 Eq. 13, u a vector)
 *     div u_I  = sum_J w(x_IJ) V_J A(u) . (M_I^-1 x_IJ)         (000 Eq. 12, from Eq. 8)
 *
 * L is the gradient of a vector field as the velocity gradient is written,
 * L_ab = du_a/dx_b (row a, column b), and div u is its trace. The curl (000 Eq. 14)
 * is the skew part of L (not provided separately).
 *
 * First-order consistency. M is symmetric, so for any linear field f = c + a . x,
 * A(f) = a . x_IJ and grad f_I = M_I^-1 (sum_J w V_J x_IJ (x) x_IJ) a = M_I^-1 M_I a = a
 * exactly, whatever the neighbours: inside, at a free surface, at a wall, on an
 * irregular cloud. The same holds for L and div u of u = c + A x. That is what M^-1
 * is for (SPH's plain kernel gradient has no such property where the support is cut).
 *
 * The neighbours. ulph_operators_update_list keeps, from candidate lists
 * (verlet_list.h), the pairs within the support, |x_IJ| < delta (coincident particles
 * included: they add nothing), in the pair-once rows of fluid_rows.h: each pair of
 * fluid particles once, in the row of the lower index, each fluid-boundary pair in the
 * fluid particle's row, and each wall or solid particle's full row; per pair it keeps
 * w(x_IJ) (w_IJ = w_JI: one kernel value per pair). Every sum above is linear in what
 * it sums, so it is taken without M_I^-1 and multiplied by it once per particle
 * (grad f_I = M_I^-1 sum_J w V_J A(f) x_IJ; L_I = B_I M_I^-1 with
 * B_I = sum_J w V_J A(u) (x) x_IJ), and a pair of fluid particles adds to both:
 * A(f) x_IJ is the same seen from either side (both change sign). The pair passes run
 * in the rows' even and odd blocks in parallel (OpenMP) and add every particle's terms
 * in an order fixed by the particles alone: the results are the same bit for bit with
 * any number of threads. Nothing is allocated unless the particle or pair count grows
 * beyond an earlier update's.
 *
 * Singular shape tensors: THE RULE. A particle I whose family cannot determine a
 * gradient has its M_I^-1 set to zero and the flag
 * ULPH_SINGULAR_SHAPE: all its gradients, velocity gradient and divergence are zero.
 * That is the case when
 *   - it has fewer than FSI_DIM + 1 neighbours at a non-zero distance within the
 *     support (an isolated particle, a particle with one neighbour, ...), or
 *   - M_I is singular, not finite, or its Frobenius condition number |M| |M^-1|
 *     exceeds max_condition (ULPH_MAX_CONDITION_M by default): neighbours (nearly)
 *     on a line (on a plane in 3D), or the computed M^-1 does not invert M
 *     (|M M^-1 - I| > 1e-8: the round-off inverse of a rank-one 3 x 3 M).
 * Its own M_I is still stored. Why zero and not a regularised inverse: an
 * ill-conditioned M^-1 turns the small offsets of a thin family into huge gradients
 * of any non-linear field (000 §3 warns of exactly this near the interface), and a
 * regularised or pseudo-inverse cancels the kernel weight (g ~ x / |x|^2 for a lone
 * neighbour, whatever its distance), so a particle entering another's support would
 * pull with full strength at once. With zero, an isolated particle (a droplet) keeps
 * its density (zero divergence) and feels no pressure gradient of its own; in the
 * pair-symmetric momentum equation (000 Eq. 23) it still takes part through its
 * neighbours' M_J^-1, so momentum stays conserved. Nothing is ever NaN or Inf for
 * finite input. The scheme may count or report the flagged particles (n_singular). */
#ifndef ULPH_OPERATORS_H
#define ULPH_OPERATORS_H

#include <stdint.h>

#include "fluid_particles.h"
#include "neighbour_grid.h"
#include "small_tensor.h"
#include "gaussian_kernel.h"
#include "verlet_list.h"
#include "fluid_pairs.h"
#include "fluid_rows.h"
#include "fluid_parallel.h"

/* Default bound on the Frobenius condition number |M| |M^-1| of a usable shape
 * tensor (ulph_operators.max_condition; at least FSI_DIM for any M). It is not about
 * round-off: a family of length L and thickness t has |M| |M^-1| ~ (L/t)^2, and a
 * curvature k of a field along it shows up as a spurious gradient across it of about
 * k L^2 / t = k L sqrt(|M| |M^-1|). Measured with h = 1.2 dx, delta = 3 h in 2D
 * (tests/unit/test_ulph_operators.c): 2.0 inside a lattice, 3.2 for any particle of a
 * lattice jittered by 0.3 dx (edges and corners included), 2.7 in a layer two
 * particles thick (4.3 jittered), up to 211 in a single jittered row of particles (a
 * wavy filament: its worst families flagged, 4 of 30); five particles on a line with
 * the middle one 0.01 dx off it give 1.3e4 (flagged), an exact line is singular.
 * 1e2, not the 1e3 it was: spray filaments thrown off a splash went unstable with
 * condition numbers of 112-187 (C5, docs/ulph.md). docs/ulph.md has the table. */
#define ULPH_MAX_CONDITION_M 1e2

/* Per-particle flags (ulph_operators.flags). */
enum {
    ULPH_SINGULAR_SHAPE = 1,    /* M^-1 unusable: M^-1 = 0, gradients zero (the rule above) */
    ULPH_IDLE_WALL = 2,         /* an idle wall (verlet_list.h): empty row, M = M^-1 = 0 */
};

/* Read-only for callers (except max_condition, which may be set before an update). */
typedef struct {
    fluid_rows rows;        /* the pairs within the support, f = w(|x_IJ|) (000 Eq. 17) */
    fsi_periodic periodic;  /* the periodic axes of the candidates (pair vectors) */
    int n;                  /* particles of the last update */
    int64_t n_pairs;        /* directed pairs within the support (each pair twice) */
    int32_t *neighbours;    /* per particle: its neighbours within the support */
    double *shape;          /* M_I (000 Eq. 15), FSI_MAT_SIZE each, row-major [m^2] */
    double *shape_inv;      /* M_I^-1, FSI_MAT_SIZE each [1/m^2]; zero for a flagged I */
    uint8_t *flags;         /* ULPH_SINGULAR_SHAPE, ULPH_IDLE_WALL */
    int32_t *informative;   /* scratch: neighbours with w V_J > 0 at a non-zero distance */
    int n_singular;         /* flagged particles at the last update */
    double max_condition;   /* bound of the rule above */
    int point_capacity;     /* allocated size */
} ulph_operators;

/* x_IJ = x_J - x_I (nearest periodic image) and |x_IJ|^2. */
static inline double ulph_pair_vector(const ulph_operators *ops, const double *x, int i, int j,
                                      double *rel)
{
    return fluid_pair_vector_r2(fsi_periodic_any(&ops->periodic) ? &ops->periodic : NULL, x,
                                i, j, rel);
}

/* Empty operators (no allocation), max_condition = ULPH_MAX_CONDITION_M. */
void ulph_operators_init(ulph_operators *ops);

/* Frees the arrays and leaves ops empty (init state, max_condition kept). */
void ulph_operators_free(ulph_operators *ops);

/* Neighbour rows, M and M^-1 of every particle of p in its current positions p->x
 * with volumes p->volume. grid must have been built from p->x (any cell size; the
 * support k->support is the natural one). Returns 0, or -1 when the grid does not
 * hold p->n points or memory runs out (ops is then empty). */
int ulph_operators_update(ulph_operators *ops, const gaussian_kernel *k,
                          const fsi_neighbour_grid *grid, const fluid_particles *p);

/* The same from candidate lists built (or kept, fluid_verlet_update) for p, with every
 * pair now within the support among them; list_rebuilt: the lists were built since the
 * last update (the rows are then derived again). An idle wall's row is empty and
 * flagged ULPH_IDLE_WALL (not counted in n_singular). ulph_operators_update is this
 * with candidates from the grid at the support itself and no idle walls. */
int ulph_operators_update_list(ulph_operators *ops, const gaussian_kernel *k,
                               const fluid_verlet *list, const fluid_particles *p,
                               int list_rebuilt);

/* Runs block(context, lo, hi) over the particles of the rows' blocks, the even blocks
 * in parallel, then the odd ones (fluid_rows.h): for a pair pass that writes to both
 * particles of a fluid pair. */
void ulph_for_blocks(const ulph_operators *ops, void (*block)(void *context, int lo, int hi),
                     void *context);

/* grad f (000 Eq. 13) of the scalar field f[n] over p's pairs: grad[i * FSI_DIM + a] =
 * df/dx_a. */
void ulph_gradient_scalar(const ulph_operators *ops, const fluid_particles *p, const double *f,
                          double *grad);

/* L = grad u (000 Eq. 13) of the vector field u[n * FSI_DIM]:
 * L[i * FSI_MAT_SIZE + a * FSI_DIM + b] = du_a/dx_b. */
void ulph_gradient_vector(const ulph_operators *ops, const fluid_particles *p, const double *u,
                          double *grad);

/* div u (000 Eq. 12) of the vector field u[n * FSI_DIM]: div[i], the trace of
 * ulph_gradient_vector's L. */
void ulph_divergence(const ulph_operators *ops, const fluid_particles *p, const double *u,
                     double *div);

#endif
