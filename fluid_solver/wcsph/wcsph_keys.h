/* The keys of the WCSPH scheme in [fluid.wcsph]. */
#ifndef WCSPH_KEYS_H
#define WCSPH_KEYS_H

#include "case_file.h"

/* h / dx of the Wendland C2 kernel (support 2h): 1.5, the value 004 states (for its
 * solid, §5.2); on a square lattice its second moment is within 0.26 % of the identity
 * (0.62 % at DualSPHysics' 1.7), which sets the hydrostatic pressure error
 * (docs/wcsph.md). */
#define WCSPH_H_OVER_DX 1.5
/* beta_1 of 004 Eq. 8 (Monaghan's alpha): 0.01, docs/wcsph.md. */
#define WCSPH_ARTIFICIAL_VISCOSITY 0.01
/* delta of 004 Eq. 6. */
#define WCSPH_DENSITY_DIFFUSION 0.1
/* k of the soft contact (004 Eq. 21). */
#define WCSPH_SOLID_CONTACT 0.01

extern const fsi_key_table fsi_wcsph_keys;

/* The kernel support 2 h = 2 smoothing_factor spacing [m] (004 Eq. 5) of the WCSPH
 * fluid of [role] (fsi_solver_spec.support). */
double wcsph_support(const fsi_case *c, const char *role);

#endif
