/* What the TLSPH model offers beyond solid_model.h, for unit tests and figures: its
 * per-point deformation gradient at given positions and its reference families.
 * Only code that links fsi_solid_tlsph on purpose (tests, bench) includes this; the
 * main loop knows the model only through solid_model.h. */
#ifndef TLSPH_H
#define TLSPH_H

#include "solid_bonds.h"
#include "solid_model.h"

/* F_i (003 Eq. 36, FSI_MAT_SIZE entries, row-major) at positions x. */
void tlsph_deformation_gradient(const solid_model *m, const double *x, int i, double *f);

/* The reference families (every point within the support 2 h). */
const solid_bonds *tlsph_families(const solid_model *m);

#endif
