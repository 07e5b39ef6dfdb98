/* The keys of the ULPH scheme (docs/cases.md is generated from this table) and the
 * support radius they give. */
#include "ulph_keys.h"

#include "verlet_list.h"

#define STR2(x) #x
#define STR(x) STR2(x)

static const fsi_key_spec keys[] = {
    {"smoothing_factor", FSI_KEY_REAL, "-", STR(ULPH_KERNEL_H_OVER_DX), FSI_BOUND_MIN_OPEN, 0,
     0, NULL, "Smoothing length over spacing, h / dx, of the kernel (000 Eq. 17: 1.2)."},
    {"support_factor", FSI_KEY_REAL, "-", STR(ULPH_KERNEL_SUPPORT_FACTOR),
     FSI_BOUND_MIN_OPEN, 0, 0, NULL,
     "Support radius over smoothing length, delta / h (000 Eq. 17: 3)."},
    {"artificial_viscosity", FSI_KEY_REAL, "-", "0.02", FSI_BOUND_MIN | FSI_BOUND_MAX, 0, 0.5,
     NULL, "Coefficient alpha of the artificial viscosity of 000 Eqs. 26-27 (000: 0 to "
     "0.5, 0.02 for the dam break of §4.2); 0 turns it off."},
    {"density_filter_interval", FSI_KEY_INT, "-", "20", FSI_BOUND_MIN, 0, 0, NULL,
     "Every this many steps the density is reset to the Shepard average of 000 Eq. 24 "
     "with a first-order correction that keeps a linear density field (docs/ulph.md; "
     "000: every 20 steps); 0 turns the filter off."},
    {"viscous_operator", FSI_KEY_CHOICE, "-", "laplacian", 0, 0, 0, "laplacian|stress",
     "laplacian: the viscous force is mu times a pairwise Laplacian of the velocity, which "
     "damps every mode; stress: tau = 2 mu e' inside sigma of 000 Eq. 23 as printed, whose "
     "nested gradients leave a velocity alternating from one particle row to the next "
     "undamped (docs/ulph.md)."},
    {"neighbour_skin", FSI_KEY_REAL, "-", STR(FLUID_VERLET_SKIN), FSI_BOUND_MIN | FSI_BOUND_MAX, 0,
     1, NULL, "Skin of the candidate neighbour lists as a fraction of the support delta: "
     "the lists hold the particles within delta (1 + skin) and are rebuilt when a particle "
     "has moved half the skin (docs/ulph.md, Cost); 0 rebuilds them at every evaluation. "
     "The neighbours within the support, and so the results, do not depend on it."},
    {"wall_contact", FSI_KEY_REAL, "-", "0.01", FSI_BOUND_MIN | FSI_BOUND_MAX, 0, 1, NULL,
     "Coefficient k of the soft contact that pushes a fluid particle away from a wall or "
     "solid particle closer than one spacing, k c0^2 (1 - r / dx) f(r / 0.75 h) / r "
     "(004 Eqs. 21-24, k = 0.01 there; docs/ulph.md): it keeps thin, fast layers without "
     "pressure out of walls and solids. Zero at one spacing and beyond; 0 turns it off."},
    {"integrator", FSI_KEY_CHOICE, "-", "predictor_corrector", 0, 0, 0,
     "predictor_corrector|verlet",
     "predictor_corrector: the predictor-corrector of 000 Eq. 56 (two evaluations of the "
     "rates a step); verlet: Monaghan's Verlet scheme (one evaluation a step, an Euler step "
     "every 40 and after every density filter; docs/ulph.md)."},
    {"tension", FSI_KEY_BOOL, "-", "false", 0, 0, 0, NULL,
     "false: the water does not sustain tension, a fluid particle's density is kept at or "
     "above rho0 (p >= 0, gauge against the atmosphere above a free surface; docs/ulph.md); "
     "true: the Tait equation both ways (000 Eq. 6)."},
};

const fsi_key_table fsi_ulph_keys = {
    "ulph",
    "Updated Lagrangian Particle Hydrodynamics (000 §2.1): the kernel, the artificial "
    "viscosity and the density filter. Its support radius, derived into [fluid] support, "
    "is smoothing_factor * support_factor * [fluid] spacing (000 Eq. 17).",
    keys, (int)(sizeof keys / sizeof keys[0])};

double ulph_support(const fsi_case *c, const char *role)
{
    const char *own = fsi_case_solver_section(c, role);
    return fsi_case_get_real(c, own, "smoothing_factor", ULPH_KERNEL_H_OVER_DX) *
           fsi_case_get_real(c, own, "support_factor", ULPH_KERNEL_SUPPORT_FACTOR) *
           fsi_case_get_real(c, role, "spacing", 0.0);
}
