/* Key tables of the example participants (docs/cases.md). */
#ifndef FSI_EXAMPLE_KEYS_H
#define FSI_EXAMPLE_KEYS_H

#include "case_file.h"

extern const fsi_key_table fsi_spring_solid_keys;
extern const fsi_key_table fsi_dashpot_fluid_keys;

#endif
