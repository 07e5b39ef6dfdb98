/* The keys of the ULPH scheme, in its solver section [fluid.ulph] (solver = ulph). */
#ifndef ULPH_KEYS_H
#define ULPH_KEYS_H

#include "case_file.h"

extern const fsi_key_table fsi_ulph_keys;

/* The kernel support delta = smoothing_factor * support_factor * spacing [m] (000
 * Eq. 17) of the ULPH fluid of [role] (fsi_solver_spec.support). */
double ulph_support(const fsi_case *c, const char *role);

#endif
