/* ISPH's pressure Poisson equation (003 Eqs. 14-17, docs/isph.md): assembled over the
 * full rows of isph_pairs.h every projection and solved with core/krylov.h, warm-started
 * from the particles' last pressure. One unknown per particle:
 *   - a fluid particle a (003 Eqs. 15-16, Skillen's blending alpha_a of Eq. 17):
 *       A_aa p_a + alpha_a sum_b A_ab p_b = alpha_a (1 / dt) sum_b V_b (u*_b - u*_a) . B_a grad_a W_ab,
 *       A_ab = -c_ab, A_aa = sum_b c_ab, c_ab = (2 V_b / rho0) x_ab . (B_a grad_a W_ab) / |x_ab|^2,
 *     blended, for alpha_a < 1, with the free-surface condition applied where the
 *     surface is, half a spacing (surface_offset) outside the particle along its
 *     normal n: p_a + surface_offset n . <grad p>_a = 0 (003 Eq. 2's gradient). A surface
 *     particle then carries the pressure of its depth below the surface, about
 *     rho0 |g| dx / 2 at rest, which is what holds it up against gravity in the pressure
 *     force's pair terms over its half support (docs/isph.md; with p = 0 there, as in
 *     Skillen et al. 2013, the surface row of a tank at rest falls at 0.48 g). A splash
 *     particle has p = 0;
 *   - a wall or solid particle S with fluid neighbours f: the dummy-particle pressure of
 *     Adami et al. 2012 (Eq. 27) as an equation between unknowns,
 *       p_S - sum_f W_Sf p_f / sum_f W_Sf = rho0 (g - a_S) . sum_f W_Sf (x_S - x_f) / sum_f W_Sf,
 *     the discrete Neumann condition dp/dn = rho0 (g - a_S) . n of a wall that moves
 *     with acceleration a_S (003 Eq. 46 for the solid). In its fluid neighbours'
 *     divergence it counts with u*_S = v_S + dt (g - a_S): the velocity whose correction
 *     by the pressure gradient of that condition, rho0 (g - a_S), leaves the wall's own
 *     v_S (a fluid at rest on a floor sees no divergence, and the pressure is exactly
 *     hydrostatic). A solid particle of known mass has its acceleration taken
 *     implicitly (last_load below, boundary_row in isph_ppe.c); its u*_S keeps the
 *     whole received a_S, which already holds the last load (fluid_row in isph_ppe.c).
 *     A wall or solid particle whose pressure comes out negative is held at p = 0 and
 *     the equation solved again (at most ISPH_WALL_PASSES times; the set carries over to
 *     the next projection): a wall pushes, never pulls;
 *   - any other particle: p = 0.
 * Every row is scaled to a unit diagonal, so the residual weighs all rows alike. With no
 * particle at p = 0 the pressure is defined up to a constant: the first fluid particle
 * is then held at its last pressure. */
#ifndef ISPH_PPE_H
#define ISPH_PPE_H

#include <stddef.h>

#include "fluid_particles.h"
#include "isph_operators.h"
#include "isph_pairs.h"
#include "krylov.h"
#include "state_store.h"

typedef struct {
    fsi_krylov_settings settings;
    /* the solid's inertia in the equation (boundary_row in isph_ppe.c): the pressure
     * load of the last step on every particle, the scheme's; NULL: the solid's
     * received acceleration is taken as it is */
    const double *last_load;
    /* the depth of structure behind a solid particle whose mass its row carries [m]
     * (solid_inertia_depth, docs/isph.md "How heavy the solid is in the PPE"): its mass
     * rho_S V_S times max(1, depth / dx_S); 0: the particle's own */
    double inertia_depth;
    fsi_precond_kind preconditioner;
    int gmres;                  /* 1: GMRES(30), 0: BiCGSTAB */
    double surface_offset;      /* where the free surface is, outside a surface particle [m] */
    fsi_csr a;
    fsi_precond m;
    double *rhs, *coef, *diag;  /* per row, per pair, per row */
    int32_t *cols;              /* one row's columns and values */
    double *vals;
    unsigned char *held;        /* per particle: 1, a wall held at p = 0 */
    int capacity, row_capacity, held_capacity;
    int64_t coef_capacity;
    /* statistics since the start */
    long solves, extra_passes;  /* projections; solves again for the walls' set */
    long long iterations;
    int worst_iterations;
    double worst_residual;
    int pinned;                 /* solves without a particle at p = 0 */
} isph_ppe;

void isph_ppe_init(isph_ppe *s, fsi_krylov_settings settings, fsi_precond_kind preconditioner,
                   int gmres, double surface_offset);
void isph_ppe_free(isph_ppe *s);

/* Assembles and solves for p->pressure of every particle, u_star the fluid's predicted
 * velocities (FSI_DIM per particle; walls and solid use p->v), dt the step, gravity g.
 * res gets the solver's report. 0; -1 with msg when memory runs out, the
 * preconditioner cannot be set up, or the solve does not converge (p->pressure then
 * holds the best iterate, finite). */
int isph_ppe_solve(isph_ppe *s, const isph_pairs *q, fluid_particles *p, const isph_fields *f,
                   const double *u_star, double dt, double rho0, const double *gravity,
                   fsi_krylov_result *res, char *msg, size_t msg_size);

/* The equation's state between projections under "<prefix>.*": the walls held at
 * p = 0 (the set carries over) and the statistics the log reports. The matrix, the
 * preconditioner and the warm start (the particles' pressure) are not its state. 0,
 * or -1 (memory; restore: no such state). */
int isph_ppe_save_state(const isph_ppe *s, fsi_state *st, const char *prefix);
int isph_ppe_restore_state(isph_ppe *s, const fsi_state *st, const char *prefix);

/* The first n particles were permuted (fluid_scheme_particles_reordered). */
void isph_ppe_reordered(isph_ppe *s, const int *sorted, int n, void *scratch);

#endif
