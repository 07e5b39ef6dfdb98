/* The rates of the ULPH fluid: continuity (000 Eq. 16) and momentum with viscous
 * stress and artificial viscosity (000 Eqs. 23, 25-28), over the neighbour lists and
 * shape tensors of ulph_operators. */
#ifndef ULPH_MOMENTUM_H
#define ULPH_MOMENTUM_H

#include "fluid_particles.h"
#include "ulph_operators.h"

typedef struct {
    double viscosity;           /* mu [Pa s] */
    double artificial_viscosity;/* alpha of 000 Eq. 26 */
    double h, c0, rho0;         /* smoothing length, sound speed, reference density */
    double gravity[FSI_DIM];
    int viscous_laplacian;      /* 1: the pairwise Laplacian below instead of tau in Eq. 23 */
    double contact;             /* k of the wall contact (soft_contact.h, 004 Eq. 21); 0: off */
    double spacing;             /* dx of the fluid: the contact reaches (dx + dx_J) / 2 [m] */
} ulph_momentum_params;

/* Scratch the rates need, n particles each: velocity gradient L (FSI_MAT_SIZE),
 * sigma M^-1 (FSI_MAT_SIZE), and the packed copy and sums of ulph_momentum.c. */
typedef struct {
    int capacity;
    double *velocity_gradient, *stress_shape;
    double *packed, *sums;      /* 64-byte aligned */
} ulph_momentum_scratch;

int ulph_momentum_reserve(ulph_momentum_scratch *s, int n);
void ulph_momentum_free(ulph_momentum_scratch *s);

/* For every fluid particle I (others get zero rates):
 *   drho_I/dt = -rho_I sum_J w V_J (v_J - v_I) . M_I^-1 x_IJ          (000 Eq. 16)
 *   rho_I dv_I/dt = sum_J w V_J (sigma_I M_I^-1 + sigma_J M_J^-1) x_IJ + Pi_I + rho_I g
 *                                                                  (000 Eqs. 23, 28)
 * with sigma = -p I + tau (000 Eq. 3), tau = 2 mu e', e' = sym(L) - tr(L) / 3 I
 * (000 Eqs. 4-5, 25; the 1/3 of a plane flow of a three-dimensional fluid, whose
 * out-of-plane rate is zero), L the velocity gradient (000 Eq. 13) of
 * velocity_for_viscosity (walls: 000 Eq. 50), and the artificial viscosity
 *   Pi_I = alpha h c0 rho0 sum_J w pi_IJ M_I^-1 x_IJ V_J                 (000 Eq. 26)
 *   pi_IJ = v_IJ . x_IJ / (|x_IJ|^2 + 0.01 h^2) if v_IJ . x_IJ < 0, else 0 (000 Eq. 27)
 * (v_IJ = v_J - v_I: negative when I and J approach; Pi_I then pushes I away from J),
 * v_J of a wall particle being its velocity_for_viscosity (the mirrored velocity of
 * 000 Eq. 50), so that a wall resists a fluid particle's approach in both slip modes.
 * With viscous_laplacian the viscous force is instead mu times the pairwise Laplacian
 *   lap u_I = 2 DIM sum_J w V_J (u_J - u_I) / ((tr M_I + tr M_J) / 2)
 * (u = velocity_for_viscosity; exact for a quadratic field where M is isotropic and the
 * first moment vanishes, since sum_J w V_J x_IJ (x) x_IJ = M_I) and tau drops out of
 * sigma: the nested gradients of Eq. 23 cannot see a field that alternates from one
 * particle row to the next (its gradient is zero at every particle), so such a mode is
 * never damped (docs/ulph.md, plane Poiseuille flow). The pressure, viscous and
 * Laplacian pair terms are antisymmetric: momentum is conserved exactly. Each pair of
 * fluid particles is evaluated once and written to both (ulph_operators.h).
 * A wall pushes, never pulls: against a wall or moving boundary particle a fluid
 * particle's pressure counts as max(p_I, 0) (with tension = true p_I may be negative,
 * and -p_I M_I^-1 would draw I into the wall).
 * Against a wall or moving boundary particle J closer than dx the pair term also carries
 * the soft contact of soft_contact.h (004 Eqs. 21-24), rho_I a_IJ, when prm->contact > 0.
 * Pressures, densities and volumes must be current (walls included). */
void ulph_momentum_rates(const ulph_operators *ops, const ulph_momentum_params *prm,
                         const fluid_particles *p, const double *velocity_for_viscosity,
                         ulph_momentum_scratch *scratch, double *drho_dt, double *dv_dt);

/* The force the fluid exerts on every moving boundary particle B (force[B * FSI_DIM + d];
 * zero for the others), from the state of the last ulph_momentum_rates call: the exact
 * reaction of the pair terms between B and its fluid neighbours I,
 *     F_B = - sum_I V_I f_IB,
 * f_IB the force density on I from B in the momentum equation (pressure, viscous,
 * artificial viscous, contact), computed by the same code as the rates' term over B's
 * own row. The forces on fluid and boundary therefore balance to round-off
 * (tests/unit/test_ulph_scheme.c) whatever the pair terms' symmetry. */
void ulph_boundary_loads(const ulph_operators *ops, const ulph_momentum_params *prm,
                         const fluid_particles *p, const double *velocity_for_viscosity,
                         const ulph_momentum_scratch *scratch, double *force);

#endif
