/* The keys of the WCSPH scheme (docs/cases.md is generated from this table). */
#include "wcsph_keys.h"

#include "verlet_list.h"

#define STR2(x) #x
#define STR(x) STR2(x)

static const fsi_key_spec keys[] = {
    {"smoothing_factor", FSI_KEY_REAL, "-", STR(WCSPH_H_OVER_DX), FSI_BOUND_MIN_OPEN, 0, 0,
     NULL, "Smoothing length over spacing, h / dx, of the Wendland C2 kernel (004 Eq. 5; "
     "support 2h). 004 states 1.5 for its solid (§5.2) and leaves the fluid's unstated "
     "(docs/wcsph.md)."},
    {"artificial_viscosity", FSI_KEY_REAL, "-", STR(WCSPH_ARTIFICIAL_VISCOSITY),
     FSI_BOUND_MIN | FSI_BOUND_MAX, 0, 1, NULL,
     "beta_1 of the artificial viscosity of 004 Eqs. 8-9 (Monaghan's alpha; 004 leaves it "
     "unstated; 0.01 after Crespo et al. 2015, docs/wcsph.md); 0 turns the linear term off."},
    {"artificial_viscosity_quadratic", FSI_KEY_REAL, "-", "0", FSI_BOUND_MIN | FSI_BOUND_MAX, 0,
     10, NULL, "beta_2 of 004 Eq. 8, the quadratic (shock) term; 0 for liquids "
     "(Monaghan 1992, docs/wcsph.md)."},
    {"density_diffusion", FSI_KEY_REAL, "-", STR(WCSPH_DENSITY_DIFFUSION),
     FSI_BOUND_MIN | FSI_BOUND_MAX, 0, 1, NULL,
     "delta of the density diffusion term of 004 Eq. 6 (delta-SPH; 0.1 in 004); 0 turns it "
     "off."},
    {"density_diffusion_form", FSI_KEY_CHOICE, "-", "molteni", 0, 0, 0, "molteni|antuono",
     "molteni: the term of 004 Eq. 6 (Molteni & Colagrossi 2009); antuono: with the "
     "renormalised density gradients of Antuono et al. 2010 (Marrone et al. 2011), which "
     "vanishes for a hydrostatic density field, at a free surface too (docs/wcsph.md)."},
    {"viscous_operator", FSI_KEY_CHOICE, "-", "stress", 0, 0, 0, "stress|laplacian",
     "stress: the viscous stress tau = mu (grad v + grad v^T) of 004 Eqs. 3 and 7; "
     "laplacian: Morris et al. 1997's pairwise viscous term, which also damps a velocity "
     "alternating from one particle row to the next (docs/wcsph.md)."},
    {"solid_coupling", FSI_KEY_CHOICE, "-", "dummy", 0, 0, 0, "dummy|contact",
     "How the fluid sees the solid's particles: dummy, as moving dummy wall particles (004 "
     "Eq. 10 with their acceleration) plus the soft contact; contact, only the soft "
     "repulsive force of 004 Eqs. 21-24 (004 §4), which acts within one spacing and cannot "
     "hold a deep column at rest (docs/wcsph.md, C4)."},
    {"solid_contact", FSI_KEY_REAL, "-", STR(WCSPH_SOLID_CONTACT), FSI_BOUND_MIN | FSI_BOUND_MAX,
     0, 1, NULL, "Coefficient k of the soft contact between a fluid particle and a solid "
     "particle closer than one spacing, k c0^2 (1 - r / dx) f(r / 0.75 h) / r (004 Eqs. "
     "21-24, k = 0.01 there); 0 turns it off."},
    {"integrator", FSI_KEY_CHOICE, "-", "predictor_corrector", 0, 0, 0,
     "predictor_corrector|verlet",
     "predictor_corrector: the predictor-corrector of 004 §4 (two evaluations a step); "
     "verlet: Monaghan's Verlet scheme as DualSPHysics uses it (one evaluation a step, an "
     "Euler step every 40)."},
    {"acoustic_step_factor", FSI_KEY_REAL, "-", "", FSI_BOUND_MIN_OPEN | FSI_BOUND_MAX, 0, 1,
     NULL, "WCSPH's own acoustic step factor, dt <= factor h / (c0 + |v|max), in place of "
     "[fluid] cfl_acoustic (empty: that one), for a case whose schemes are stable at "
     "different steps."},
    {"neighbour_skin", FSI_KEY_REAL, "-", STR(FLUID_VERLET_SKIN), FSI_BOUND_MIN | FSI_BOUND_MAX, 0,
     1, NULL, "Skin of the candidate neighbour lists as a fraction of the support 2h; 0 "
     "rebuilds them at every evaluation. The neighbours within the support, and so the "
     "results, do not depend on it."},
};

const fsi_key_table fsi_wcsph_keys = {
    "wcsph",
    "Weakly compressible SPH with delta-SPH (004 §2): the Wendland kernel, artificial "
    "viscosity, density diffusion, dummy walls and the coupling with a solid.",
    keys, (int)(sizeof keys / sizeof keys[0])};

double wcsph_support(const fsi_case *c, const char *role)
{
    return 2.0 * fsi_case_get_real(c, fsi_case_solver_section(c, role), "smoothing_factor",
                                   WCSPH_H_OVER_DX) *
           fsi_case_get_real(c, role, "spacing", 0.0);
}
