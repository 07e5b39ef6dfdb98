/* The rates of WCSPH with delta-SPH (004 §2): continuity with density diffusion
 * (004 Eq. 6), momentum with the viscous stress and artificial viscosity (004 Eqs. 7-9),
 * the soft contact with solid particles (004 Eqs. 21-24, contact/soft_contact.h) and
 * the exact reaction of every fluid-boundary pair term (the loads on the solid).
 *
 * Notation: x_IJ = x_J - x_I (nearest periodic image), grad_I W_IJ = -F x_IJ with
 * F = (dW/dr) / r <= 0 (wendland_c2.h), V_J = m_J / rho_J, u the velocity the viscous
 * terms see (velocity_for_viscosity: a fluid particle's own, a dummy particle's mirrored
 * one, walls/ghost_walls.h). The sums run over the particles "in the sums": fluid and
 * wall particles, and the solid's (moving boundary) particles when they are dummy
 * particles (solid_dummy); a solid particle that is not in the sums meets the fluid
 * through the soft contact alone (004 §4). */
#ifndef WCSPH_RATES_H
#define WCSPH_RATES_H

#include <stdint.h>

#include "fluid_particles.h"
#include "tait_eos.h"
#include "verlet_list.h"
#include "fluid_rows.h"
#include "wendland_c2.h"

/* Bound on the Frobenius condition number of the renormalisation matrix: beyond it (a
 * particle with its neighbours nearly on a line, a lone spray particle) L = 0 and the
 * corrected gradient is zero, so Antuono's term falls back to Molteni's for that pair
 * side rather than amplify noise. Inside a lattice it is 2 (FSI_DIM). */
#define WCSPH_MAX_CONDITION 1e2

typedef struct {
    double h, c0, rho0, gamma;  /* smoothing length, sound speed, density, Tait exponent */
    double viscosity;           /* mu [Pa s] */
    double beta1, beta2;        /* 004 Eq. 8 */
    double delta;               /* 004 Eq. 6 */
    int antuono;                /* 1: Antuono et al. 2010's corrected diffusion */
    int laplacian;              /* 1: Morris et al. 1997's viscous term instead of tau */
    int solid_dummy;            /* 1: moving boundary particles are dummy particles */
    double contact;             /* k of 004 Eq. 21; 0: off */
    double spacing;             /* dx of the fluid [m] */
    double gravity[FSI_DIM];
} wcsph_params;

/* Per particle: p / rho^2, the sound speed, tau / rho^2 and the renormalised density
 * gradient; per particle accumulators of the passes. */
typedef struct {
    int capacity;
    double *pressure_rho2, *sound, *tau_rho2, *density_gradient;
    double *renorm_sum;         /* sum_J V_J x_IJ (x) grad_I W_IJ (antuono) */
    double *diffusion;          /* D_I below */
    long long pairs;            /* pairs within the support in the last wcsph_rates */
} wcsph_scratch;

int wcsph_scratch_reserve(wcsph_scratch *s, int n);
void wcsph_scratch_free(wcsph_scratch *s);

/* What the passes walk: the Verlet candidates (full rows, for the walls' and solid's
 * own sums), the WCSPH rows built from them (fluid_rows.h), the kernel. */
typedef struct {
    const fluid_verlet *list;
    const fluid_rows *rows;
    const wendland_c2_kernel *kernel;
} wcsph_neighbours;

/* Whether particle j takes part in the SPH sums (not only the contact). */
static inline int wcsph_in_sums(const wcsph_params *prm, const fluid_particles *p, int j)
{
    return (p->flags[j] & (FLUID_PARTICLE_FLUID | FLUID_PARTICLE_WALL)) ||
           (prm->solid_dummy && (p->flags[j] & FLUID_PARTICLE_MOVING_BOUNDARY));
}

/* The pairs of the rows now within the support with their F (wendland_c2.h), from the
 * rows' candidates (fluid_rows_build, without boundary rows). */
void wcsph_pairs(fluid_rows *rows, const wendland_c2_kernel *k, const fsi_periodic *per,
                 const fluid_particles *p);

/* Pass 1, every wall and solid particle with a row: its state from the fluid within
 * the support (walls/ghost_walls.h, 004 Eqs. 10-11); u (the velocity the viscous terms
 * see) of every particle. Fluid pressures and volumes must be current. */
void wcsph_walls(const wcsph_neighbours *nb, const tait_eos *eos, const double *gravity,
                 const unsigned char *free_slip, fluid_particles *p, double *u);

/* Pass 2: p / rho^2 and the sound speed c_I = c0 (rho_I / rho0)^((gamma - 1) / 2) of
 * every particle; unless the viscous operator is the Laplacian, the viscous stress of
 * 004 Eq. 3 from the SPH velocity gradient
 *     grad u_I = sum_J V_J (u_J - u_I) (x) grad_I W_IJ,  tau_I = mu (grad u + grad u^T),
 * stored as tau_I / rho_I^2; with antuono the renormalised density gradient
 * (Antuono et al. 2010, Eq. 2.6 there)
 *     <grad rho>_I = sum_J (rho_J - rho_I) L_I grad_I W_IJ V_J,
 *     L_I = (sum_J V_J x_IJ (x) grad_I W_IJ)^-1 (zero where it is singular),
 * exact for a linear density field wherever L_I exists. Sums over the particles in the
 * sums within the support; walls' states from pass 1. */
void wcsph_gradients(const wcsph_neighbours *nb, const wcsph_params *prm,
                     const fluid_particles *p, const double *u, wcsph_scratch *s);

/* Pass 3, every fluid particle I (others get zero rates):
 *   drho_I/dt = sum_J m_J (v_I - v_J) . grad_I W_IJ + delta h c0 D_I        (004 Eq. 6)
 *     molteni:  D_I = sum_J 2 V_J (rho_I - rho_J) (x_I - x_J) . grad_I W_IJ
 *                                             / (|x_IJ|^2 + 0.01 h^2)
 *     antuono:  D_I = sum_J V_J psi_IJ . grad_I W_IJ,
 *               psi_IJ = 2 (rho_J - rho_I) x_IJ / |x_IJ|^2 - (<grad rho>_I + <grad rho>_J)
 *               (<grad rho>_I for <grad rho>_J when J is not a fluid particle)
 *   dv_I/dt = sum_J m_J (tau_I / rho_I^2 + tau_J / rho_J^2 - pi_IJ I) grad_I W_IJ
 *             - sum_J m_J (p_I / rho_I^2 + p_J / rho_J^2) grad_I W_IJ + g + contact
 *                                                                          (004 Eq. 7)
 *   pi_IJ = (-beta1 c_IJ mu_IJ + beta2 mu_IJ^2) / rho_IJ when v_IJ . x_IJ < 0 (Eq. 8)
 *   mu_IJ = h v_IJ . (x_I - x_J) / (|x_IJ|^2 + 0.01 h^2)                     (Eq. 9)
 * (c_IJ, rho_IJ the pair's means; v in continuity is the particles' own velocity, u in
 * the viscous terms). With laplacian the tau terms are replaced by
 *   sum_J m_J 2 mu (x_I - x_J) . grad_I W_IJ / (rho_I rho_J (|x_IJ|^2 + 0.01 h^2)) (u_I - u_J).
 * Against a particle that is not fluid p_I counts as max(p_I, 0): a wall pushes, never
 * pulls. Against a solid particle J closer than (dx + dx_J) / 2 the soft contact of
 * soft_contact.h adds k c0^2 zeta f (x_I - x_J) / r^2. Every pair term between fluid
 * particles is antisymmetric (m_I times it): it is evaluated once per pair
 * (fluid_rows.h) and momentum is conserved to round-off. Passes 1 and 2 must have run. */
void wcsph_rates(const wcsph_neighbours *nb, const wcsph_params *prm, const fluid_particles *p,
                 const double *u, wcsph_scratch *s, double *drho_dt, double *dv_dt);

/* The density diffusion term delta h c0 D_I alone (the rates' second term), for every
 * particle (0 for non-fluid ones), summed over each fluid particle's full row: a
 * reference for the rates' pair-once sums. */
void wcsph_density_diffusion(const wcsph_neighbours *nb, const wcsph_params *prm,
                             const fluid_particles *p, const wcsph_scratch *s, double *out);

/* The force the fluid exerts on every moving boundary particle B, force[B * FSI_DIM]
 * (zero for others): F_B = -sum_I m_I a_IB over its fluid neighbours I, a_IB the pair's
 * term in dv_I/dt above (the contact, and with solid_dummy the pressure, viscous and
 * artificial viscous terms), computed by the same code from the state of the last
 * evaluation: the loads balance the fluid's pair forces to round-off. */
void wcsph_boundary_loads(const wcsph_neighbours *nb, const wcsph_params *prm,
                          const fluid_particles *p, const double *u, const wcsph_scratch *s,
                          double *force);

/* The renormalised gradient of the scalar field f of every particle (zero where L is
 * singular): sum_J (f_J - f_I) L_I grad_I W_IJ V_J over the particles in the sums. */
void wcsph_gradient(const wcsph_neighbours *nb, const wcsph_params *prm,
                    const fluid_particles *p, const double *f, double *grad);

#endif
