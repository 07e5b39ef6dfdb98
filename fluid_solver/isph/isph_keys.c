/* The keys of the ISPH scheme (docs/cases.md is generated from this table). */
#include "isph_keys.h"

#include "verlet_list.h"

#define STR2(x) #x
#define STR(x) STR2(x)

static const fsi_key_spec keys[] = {
    {"smoothing_factor", FSI_KEY_REAL, "-", STR(ISPH_H_OVER_DX), FSI_BOUND_MIN_OPEN, 0, 0, NULL,
     "Smoothing length over spacing, h / dx, of the cubic B-spline (support 2h); 1.2 in 003 "
     "§2.1."},
    {"courant_number", FSI_KEY_REAL, "-", STR(ISPH_COURANT), FSI_BOUND_MIN_OPEN | FSI_BOUND_MAX,
     0, 1, NULL,
     "Cr of the step dt = Cr h / |u|max (003 Eq. 49; 0.1 in 003). The step is also bounded "
     "by 0.25 sqrt(h / |a|max) and 0.125 h^2 / nu: there is no sound speed."},
    {"gradient_correction", FSI_KEY_CHOICE, "-", "bonet_lok", 0, 0, 0, "bonet_lok|none",
     "bonet_lok: the gradients, the divergence and the Poisson equation's Laplacian with the "
     "correction B_a of 003 Eq. 5; none: with the kernel's own gradient (Cummins & Rudman "
     "1999, Shao & Lo 2003)."},
    {"ppe_tolerance", FSI_KEY_REAL, "-", STR(ISPH_PPE_TOLERANCE),
     FSI_BOUND_MIN_OPEN | FSI_BOUND_MAX, 0, 0.1, NULL,
     "Relative residual ||b - A p|| / ||b|| at which the pressure Poisson equation (003 Eqs. "
     "15-16, rows scaled to a unit diagonal) counts as solved. A solve that does not reach "
     "it within ppe_max_iterations stops the run (docs/isph.md)."},
    {"ppe_max_iterations", FSI_KEY_INT, "-", STR(ISPH_PPE_MAX_ITERATIONS), FSI_BOUND_MIN, 1, 0,
     NULL, "Iterations of the Krylov solver before a pressure solve counts as failed."},
    {"ppe_solver", FSI_KEY_CHOICE, "-", "bicgstab", 0, 0, 0, "bicgstab|gmres",
     "bicgstab: BiCGSTAB (van der Vorst 1992); gmres: GMRES(30), whose residual cannot rise "
     "within a cycle (core/krylov.h, docs/isph.md's measurements)."},
    {"ppe_preconditioner", FSI_KEY_CHOICE, "-", "ilu0", 0, 0, 0, "ilu0|jacobi",
     "ilu0: incomplete LU on the matrix's own pattern (5-6 times fewer iterations, "
     "sequential); jacobi: the diagonal (parallel)."},
    {"shifting", FSI_KEY_REAL, "-", STR(ISPH_SHIFTING), FSI_BOUND_MIN | FSI_BOUND_MAX, 0, 1, NULL,
     "C of the particle shifting of 003 Eqs. 21-23 (Xu et al. 2009; 0.01-0.1 in 003), the "
     "shift C |u|max dt R_a capped at 0.2 h (Lind et al. 2012); 0 turns shifting off."},
    {"fsi_shifting_layer", FSI_KEY_REAL, "-", STR(ISPH_FSI_LAYER), FSI_BOUND_MIN_OPEN, 0, 0,
     NULL, "|d| |R_n| / (|u|max dt) of 003 Eqs. 27-30 (5 to 50 there): the depth of the "
     "layer over which a fluid particle next to the solid has the normal part of its shift "
     "damped exponentially (our reading of the underspecified equations, docs/isph.md)."},
    {"smagorinsky", FSI_KEY_REAL, "-", STR(ISPH_SMAGORINSKY), FSI_BOUND_MIN | FSI_BOUND_MAX, 0,
     1, NULL, "c_s of the sub-particle-scale eddy viscosity nu_t = (c_s h)^2 sqrt(2 S:S) (003 "
     "Eq. 10, Gotoh et al. 2000; 0.1 in 003); 0 leaves the molecular viscosity alone."},
    {"free_surface_lower", FSI_KEY_REAL, "-", STR(ISPH_SURFACE_LOWER), FSI_BOUND_MIN_OPEN, 0, 0,
     NULL, "div r at and below which a particle is on the free surface (p = 0; 003 Eq. 17, "
     "Skillen et al. 2013: 1.4 in 2D)."},
    {"free_surface_upper", FSI_KEY_REAL, "-", STR(ISPH_SURFACE_UPPER), FSI_BOUND_MIN_OPEN, 0, 0,
     NULL, "div r at and above which a particle's Poisson equation is whole (003 Eq. 17: "
     "1.6); between the two it is blended by 0.5 (1 - cos(pi (div r - lower) / (upper - "
     "lower)))."},
    {"free_surface_offset", FSI_KEY_REAL, "-", STR(ISPH_SURFACE_OFFSET), FSI_BOUND_MIN |
     FSI_BOUND_MAX, 0, 1, NULL,
     "Where the free surface is, outside a surface particle along its normal, in spacings: "
     "the surface condition p = 0 is applied there (p_a = -offset dx n . grad p), so that a "
     "surface particle carries the pressure of its depth; 0 puts p = 0 on the particle "
     "itself, as 003 and Skillen et al. 2013 do (docs/isph.md)."},
    {"wall_contact", FSI_KEY_REAL, "-", STR(ISPH_WALL_CONTACT), FSI_BOUND_MIN | FSI_BOUND_MAX, 0,
     1, NULL,
     "k of the soft contact k c0^2 (1 - r / dx) f(r / 0.75 h) / r between a fluid particle "
     "and a wall or solid particle closer than one spacing (004 Eqs. 21-24, k = 0.01 there; "
     "c0 the case's [fluid] sound speed, here only the contact's stiffness scale): it keeps "
     "particles without a Poisson equation of their own (surface, splash) out of the walls; "
     "0 turns it off."},
    {"wall_hold", FSI_KEY_BOOL, "-", "true", 0, 0, 0, NULL,
     "A fluid particle that a step took into a [fluid.wall] box (axis-aligned) from outside "
     "is put back on the face it came through, its velocity into the wall set to the "
     "wall's: a kinematic non-penetration constraint behind the soft contact, which stops "
     "only particles slower than sqrt(wall_contact) c0 (docs/isph.md); the fluid log "
     "counts the particles put back. Not the solid's particles."},
    {"solid_inertia", FSI_KEY_CHOICE, "-", "in_poisson", 0, 0, 0, "in_poisson|explicit",
     "in_poisson: each solid particle's acceleration in its Poisson row is its received "
     "one without the fluid's last load plus the load the solve gives it over its mass "
     "(the structure's inertia in the PPE, 003 §2.3; stable against added mass); "
     "explicit: the received acceleration as it is, which an incompressible fluid makes "
     "unstable whenever the added mass exceeds the structure's (docs/isph.md, Coupling)."},
    {"solid_inertia_depth", FSI_KEY_REAL, "m", "0", FSI_BOUND_MIN, 0, 0, NULL,
     "With solid_inertia = in_poisson: each solid particle's mass in its Poisson row is "
     "rho_S V_S times max(1, depth / dx_S), the structure behind it to this depth moving "
     "with it. 0: the particle's own mass. Too light, the water drifts off a stiff plate "
     "and gains energy; too heavy (the whole thickness of a thin plate), the explicit "
     "exchange feeds the solid (docs/isph.md, How heavy the solid is in the PPE)."},
    {"neighbour_skin", FSI_KEY_REAL, "-", STR(FLUID_VERLET_SKIN), FSI_BOUND_MIN | FSI_BOUND_MAX, 0,
     1, NULL, "Skin of the candidate neighbour lists as a fraction of the support 2h; the "
     "results do not depend on it."},
};

const fsi_key_table fsi_isph_keys = {
    "isph",
    "Incompressible SPH (003 §2.1): a projection with a pressure Poisson equation solved "
    "every step, free-surface detection, particle shifting, dummy walls as unknowns.",
    keys, (int)(sizeof keys / sizeof keys[0])};

double isph_support(const fsi_case *c, const char *role)
{
    return 2.0 * fsi_case_get_real(c, fsi_case_solver_section(c, role), "smoothing_factor",
                                   ISPH_H_OVER_DX) *
           fsi_case_get_real(c, role, "spacing", 0.0);
}
