/* Ghost wall particles (000 §2.3; the dummy particles of Adami et al. 2012, whose
 * Eq. 27 is the pressure below) and moving boundary particles (the solid seen by the
 * fluid, 000 §3, treated the same way as no-slip walls): their pressure, density, mass
 * and the velocity they show the viscous stress, interpolated from the fluid particles
 * in their support at every evaluation of the rates. */
#ifndef FSI_GHOST_WALLS_H
#define FSI_GHOST_WALLS_H

#include "fluid_particles.h"
#include "tait_eos.h"
#include "fluid_rows.h"

/* For every wall or moving boundary particle S with fluid neighbours f in its own row
 * of rows (fluid_rows.h, built with boundary rows and filtered, rows->f holding the
 * kernel weights w_Sf of the current evaluation; per: the periodic axes or NULL):
 *   p_S = max(0, (sum_f p_f w_Sf + (g - a_S) . sum_f rho_f (x_S - x_f) w_Sf) / sum_f w_Sf)
 *                                                          (000 Eq. 52)
 * with a_S = p->boundary_acceleration of S: a moving wall's prescribed acceleration
 * (fluid_wall_motion.h), a solid particle's received one (fluid_boundary.h). In the
 * wall's frame the fluid feels g - a_S, so this continues the hydrostatic field of an
 * accelerating tank exactly (tests/unit/test_ulph_scheme.c).
 *   rho_S from the equation of state (000 Eq. 53, tait_eos.h), m_S = rho_S V0 (Eq. 54)
 *   v~_S = sum_f v_f w_Sf / sum_f w_Sf                     (000 Eq. 51)
 *   velocity_for_viscosity_S = 2 v_S - v~_S                (no-slip, 000 Eq. 50)
 *                            = v~_S - 2 ((v~_S - v_S) . n_S) n_S   (free-slip walls,
 *                                                         free_slip[S], S < its size)
 * with n_S the unit vector from S towards the weighted centre of its fluid neighbours.
 * The bound p_S >= 0 is "a wall pushes, never pulls": a wall cannot hold water by
 * suction, and a negative p_S (a stretched layer over the wall) drew the F1 front
 * into the floor. Free-slip mirrors only the normal velocity: the tangential one is the
 * fluid's (no shear), the normal one is reversed, so the viscous and artificial
 * viscous terms still resist an approach (with v~_S alone nothing did and the F1 front
 * sank through the floor). A wall particle without fluid neighbours gets p = 0,
 * rho = rho0 and v~ = v_S (its velocity_for_viscosity is then its own velocity). For
 * fluid particles velocity_for_viscosity is their velocity. */
void ghost_walls_update(const fluid_rows *rows, const fsi_periodic *per, const tait_eos *eos,
                        const double *gravity, const unsigned char *free_slip, fluid_particles *p,
                        double *velocity_for_viscosity);

/* The same for a scheme that walks its own rows: the sums of one wall particle S over
 * its fluid neighbours f, then its state from them (ghost_walls_update is these two
 * over the rows). */
typedef struct {
    double sum_w, sum_pw, head[FSI_DIM], v_mean[FSI_DIM], toward[FSI_DIM];
} ghost_wall_sums;

/* Fluid particle f at xsf = x_f - x_S with kernel weight w. */
static inline void ghost_wall_sums_add(ghost_wall_sums *g, const fluid_particles *p, int f,
                                       double w, const double *xsf)
{
    g->sum_w += w;
    g->sum_pw += p->pressure[f] * w;
    for (int d = 0; d < FSI_DIM; d++) {
        g->head[d] -= p->density[f] * xsf[d] * w;
        g->toward[d] += xsf[d] * w;
        g->v_mean[d] += p->v[f * FSI_DIM + d] * w;
    }
}

/* Pressure, density, mass and velocity_for_viscosity of wall or moving boundary
 * particle s from its sums (the equations above). */
void ghost_wall_set(const ghost_wall_sums *g, int s, const tait_eos *eos,
                    const double *gravity, const unsigned char *free_slip,
                    fluid_particles *p, double *velocity_for_viscosity);

#endif
