/* Units of extensive quantities in this build's dimension, as the output names them
 * (docs/output.md): a 2-D run is a slice of unit thickness, so its masses, volumes,
 * forces and energies are per metre of thickness. */
#ifndef FSI_UNITS_H
#define FSI_UNITS_H

#include "dim.h"

#if FSI_DIM == 2
#define FSI_UNIT_MASS "kg/m"
#define FSI_UNIT_VOLUME "m^2"
#define FSI_UNIT_FORCE "N/m"
#define FSI_UNIT_ENERGY "J/m"
#define FSI_UNIT_MOMENT "N"
#define FSI_PER_THICKNESS " (per metre of thickness in 2-D)"
#else
#define FSI_UNIT_MASS "kg"
#define FSI_UNIT_VOLUME "m^3"
#define FSI_UNIT_FORCE "N"
#define FSI_UNIT_ENERGY "J"
#define FSI_UNIT_MOMENT "N m"
#define FSI_PER_THICKNESS ""
#endif

#endif
