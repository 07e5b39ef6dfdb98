/* The keys of the ULPH scheme, in its solver section [fluid.ulph] (solver = ulph). */
#ifndef ULPH_KEYS_H
#define ULPH_KEYS_H

#include "case_file.h"

/* The seed paper's kernel (000 §2.1.3, after Eq. 17): h = 1.2 dx, delta = 3 h. */
#define ULPH_KERNEL_H_OVER_DX 1.2
#define ULPH_KERNEL_SUPPORT_FACTOR 3.0

extern const fsi_key_table fsi_ulph_keys;

/* The kernel support delta = smoothing_factor * support_factor * spacing [m] (000
 * Eq. 17) of the ULPH fluid of [role] (fsi_solver_spec.support). */
double ulph_support(const fsi_case *c, const char *role);

#endif
