/* Case keys every fluid scheme has, the fluid's object sections (water blocks, walls,
 * probes) and the semantic check of its geometry: what the launcher's solver registry
 * needs to validate a [fluid] section before any fluid runs.
 *
 * A fluid scheme's solver spec (launch/solver_registry.c) lists
 *     key_tables = { &fsi_fluid_common_keys, &fsi_<scheme>_keys }
 *     objects    = fsi_fluid_object_kinds, n_objects = FSI_FLUID_N_OBJECT_KINDS
 *     check      = fluid_geometry_check */
#ifndef FSI_FLUID_KEYS_H
#define FSI_FLUID_KEYS_H

#include <stdio.h>

#include "case_file.h"

/* [fluid]: spacing, density, viscosity, sound_speed, max_velocity, max_pressure,
 * tait_exponent, gravity, initial_pressure, cfl_acoustic, cfl_viscous, cfl_force,
 * periodic, periodic_min, periodic_max, energy_growth_limit. */
extern const fsi_key_table fsi_fluid_common_keys;

/* [fluid.block NAME], [fluid.wall NAME], [fluid.probe NAME]. */
extern const fsi_key_table fsi_fluid_block_keys;
extern const fsi_key_table fsi_fluid_wall_keys;
extern const fsi_key_table fsi_fluid_probe_keys;

#define FSI_FLUID_N_OBJECT_KINDS 3
extern const fsi_object_kind fsi_fluid_object_kinds[FSI_FLUID_N_OBJECT_KINDS];

/* The check hook of every fluid scheme (fsi_solver_spec.check): boxes with min >= max
 * or not a whole number of spacings, water and walls (or two of either) overlapping,
 * probes outside the water, a sound speed that cannot be derived, a period box that is
 * missing, too short, not a whole number of spacings or cuts a box. One line
 * "FILE:LINE: [section] key: message" per problem on 'errors'; returns how many.
 * Defined in fluid_check.c. */
int fluid_geometry_check(const fsi_case *c, const char *role, FILE *errors);

#endif
