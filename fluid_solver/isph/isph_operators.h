/* ISPH's operators over the full rows of isph_pairs.h (003 §2.1, docs/isph.md):
 *   - the Bonet-Lok correction B_a = [sum_b V_b (x_b - x_a) (x) grad_a W_ab]^-1 (003
 *     Eq. 5), used by the gradients and the Poisson equation;
 *   - the free surface from div r = sum_b V_b (x_b - x_a) . grad_a W_ab with the
 *     uncorrected kernel (with B_a it would be exactly the dimension), Skillen's blending
 *     coefficient (003 Eq. 17) and the surface normals (Eqs. 25-26);
 *   - the velocity the viscous term sees at a wall or solid particle (no-slip: 2 v_S -
 *     v~_S, Adami et al. 2012), the corrected velocity gradient, the sub-particle-scale
 *     eddy viscosity (003 Eq. 10);
 *   - the forces: viscous and pressure, both as pair terms that are antisymmetric
 *     between two particles (docs/isph.md: why not 003 Eqs. 13 and 18 as printed), so
 *     that the loads on the solid are their exact reaction. */
#ifndef ISPH_OPERATORS_H
#define ISPH_OPERATORS_H

#include <stdint.h>

#include "fluid_particles.h"
#include "isph_pairs.h"

/* Where a fluid particle is (003 Fig. 2). */
enum {
    ISPH_INTERIOR = 0,
    ISPH_NEAR_SURFACE = 1,  /* within h of a surface particle: its normal, tangential
                             * shifting only (003 Eq. 24) */
    ISPH_SURFACE = 2,       /* div r <= lower: p = 0 */
    ISPH_SPLASH = 3,        /* too few neighbours for a gradient, or no fluid among them:
                             * p = 0, not shifted */
};

typedef struct {
    int correct;            /* 1: B_a as above; 0: B_a = I (the kernel's own gradient) */
    int capacity;
    double *b;              /* B_a, FSI_DIM^2 per particle (fluid) */
    double *div_r;          /* div r (fluid) */
    double *alpha;          /* Skillen's coefficient, 003 Eq. 17 (fluid) */
    uint8_t *where;         /* ISPH_* (fluid) */
    double *normal;         /* unit outward normal of a surface or near-surface particle */
    double *v_visc;         /* the velocity the viscous term sees: v (fluid), 2 v_S - v~_S
                             * (no-slip wall or solid), FSI_DIM each */
    double *sum_w;          /* sum of W over a wall or solid particle's fluid neighbours */
    double *grad_u;         /* corrected velocity gradient du_d/dx_k at [d * DIM + k] */
    double *nu;             /* nu + nu_t [m^2/s] (fluid), nu (others) */
    double *solid_normal;   /* fluid next to the solid: unit vector from the nearest solid
                             * particle; zero elsewhere */
} isph_fields;

void isph_fields_init(isph_fields *f);
void isph_fields_free(isph_fields *f);
/* Room for n particles. 0, or -1 when memory runs out. */
int isph_fields_reserve(isph_fields *f, int n);

/* B_a and div r of every fluid particle. */
void isph_geometry(const isph_pairs *q, const fluid_particles *p, isph_fields *f);

/* Classes, Skillen's alpha and normals of every fluid particle from div r (lower,
 * upper: 003 Eq. 17's 1.4 and 1.6 in 2D), h the smoothing length. The normal leaves out
 * the walls held at p = 0 (held, isph_ppe.h; may be NULL): a dry wall above the surface
 * would tilt it at a corner. */
void isph_free_surface(const isph_pairs *q, const fluid_particles *p, const unsigned char *held,
                       double lower, double upper, double h, isph_fields *f);

/* sum_w and v_visc of every particle from the current velocities (free_slip: per
 * particle, 1 for a free-slip wall, which the viscous term then skips), and the
 * direction to the nearest solid particle of every fluid particle next to one. */
void isph_wall_velocity(const isph_pairs *q, const fluid_particles *p,
                        const unsigned char *free_slip, isph_fields *f);

/* grad_u of every fluid particle from v_visc, and nu = nu0 + (cs h)^2 sqrt(2 S:S)
 * (003 Eq. 10; nu0 for the others). */
void isph_velocity_gradient(const isph_pairs *q, const fluid_particles *p, double nu0,
                            double cs, double h, isph_fields *f);

/* The soft contact of fluid against walls and solid (contact/soft_contact.h, 004 Eqs.
 * 21-24): a particle whose Poisson equation is off (surface, splash) has nothing else to
 * keep it out of a wall it falls onto. */
typedef struct {
    double k_c2;            /* k c0^2 [m^2/s^2]; 0: off */
    double inv_eta_scale;   /* 1 / (0.75 h) [1/m] */
} isph_contact;

/* The viscous acceleration of every fluid particle, the pair term
 *   a_a = sum_b V_b (nu_a + nu_b) F_ab (u_a - u_b)
 * (Morris et al. 1997 with 003 Eq. 13's mean viscosity; u_b = v_visc), plus the soft
 * contact with walls and solid (contact may be NULL), into acc (overwritten; zero for
 * the others). */
void isph_viscous_acceleration(const isph_pairs *q, const fluid_particles *p,
                               const unsigned char *free_slip, const isph_fields *f,
                               const isph_contact *contact, double *acc);

/* Adds the pressure acceleration of every fluid particle, the pair term
 *   a_a = -(1 / rho0) sum_b V_b (p_a + p_b) grad_a W_ab
 * (Shao & Lo 2003 at constant density), to acc. A wall or solid particle held at p = 0
 * (held[b], isph_ppe.h: dry, above a free surface) exerts none: with the fluid's own
 * p_a in the pair term it would push the water along a wall away from it. */
void isph_pressure_acceleration(const isph_pairs *q, const fluid_particles *p,
                                const unsigned char *held, double rho0, double *acc);

/* The corrected gradient of a scalar s at every fluid particle, 003 Eq. 2:
 * sum_b V_b (s_b - s_a) B_a grad_a W_ab (exact for a linear field), into grad (zero
 * for the others). */
void isph_scalar_gradient(const isph_pairs *q, const fluid_particles *p, const isph_fields *f,
                          const double *s, double *grad);

/* The force on every solid particle (zero for the others): minus the pressure pair terms
 * its fluid neighbours get from it. */
void isph_pressure_loads(const isph_pairs *q, const fluid_particles *p,
                         const unsigned char *held, double *force);

/* The same for the viscous and contact pair terms. */
void isph_viscous_loads(const isph_pairs *q, const fluid_particles *p, const isph_fields *f,
                        const isph_contact *contact, double rho0, double *force);

#endif
