/* Case keys every solid model has, the object sections of the solid (blocks,
 * regions, probes) and the semantic check of its geometry: what the launcher's
 * solver registry needs to validate a [solid] section before any solid runs.
 *
 * A solid model's solver spec (launch/solver_registry.c) lists, in this order,
 *     key_tables = { &fsi_solid_common_keys, &<material table>, &fsi_<model>_keys }
 *     objects    = fsi_solid_object_kinds, n_objects = FSI_SOLID_N_OBJECT_KINDS
 *     check      = solid_geometry_check
 * Nothing here needs a model or a material, so the registry links only
 * fsi_solid_common for it. */
#ifndef FSI_SOLID_KEYS_H
#define FSI_SOLID_KEYS_H

#include <stdio.h>

#include "case_file.h"

/* [solid]: spacing, time_step_safety, damping, gravity, initial_velocity,
 * mode_amplitude, mode_length, mode_origin, energy_growth_limit. */
extern const fsi_key_table fsi_solid_common_keys;

/* Upper bound of time_step_safety. Values in (1, max] run past the model's estimated
 * stable step on purpose (the main loop warns); the bound only keeps typos such as
 * 80 for 0.8 out. */
#define SOLID_TIME_STEP_SAFETY_MAX 4.0

/* Keys of the object sections [solid.block NAME], [solid.region NAME],
 * [solid.probe NAME], [solid.crack NAME]. */
extern const fsi_key_table fsi_solid_block_keys;
extern const fsi_key_table fsi_solid_region_keys;
extern const fsi_key_table fsi_solid_probe_keys;
extern const fsi_key_table fsi_solid_crack_keys;

/* block (at least one), region, probe, crack. The count is a macro too, so that a
 * registry's static solver table can use it (an extern const int is not a constant
 * expression in C). */
#define FSI_SOLID_N_OBJECT_KINDS 4
extern const fsi_object_kind fsi_solid_object_kinds[FSI_SOLID_N_OBJECT_KINDS];
extern const int fsi_solid_n_object_kinds;

/* The check hook of every solid model (fsi_solver_spec.check): overlapping blocks,
 * blocks thinner than one spacing or not a whole number of spacings long, boxes
 * with min > max, regions and probes that select no particle, load keys on a region
 * that does not load, missing mode keys. Each problem is one line
 * "FILE:LINE: [section] key: message" on 'errors'; returns how many. Defined in
 * solid_check.c; it builds no particles, only counts lattice points. */
int solid_geometry_check(const fsi_case *c, const char *role, FILE *errors);

/* The solid's sub-step estimated from the case (time_step_safety times the material's
 * lattice bound) against FSI_MIN_STEP and FSI_MAX_STEPS up to end_time (case_check.h).
 * One line per problem on 'errors'; returns how many. Defined in solid_step_check.c. */
int solid_step_check(const fsi_case *c, const char *role, FILE *errors);

/* What a solid model accepts of the shared keys, for its check hook. */
typedef struct {
    const char *model;      /* its solver name, for messages */
    int stateless;          /* its force is a function of positions alone: RK4 allowed */
    const char *state;      /* what it commits per evaluation (messages; NULL if none) */
    int incremental;        /* takes drucker_prager (an incremental update) */
    int total_form;         /* takes saint_venant_kirchhoff and neo_hookean (laws of F) */
} solid_model_traits;

/* integrator = rk4 with a model that commits state, and constitutive laws the model
 * cannot evaluate. One line per problem on 'errors'; returns how many. Defined in
 * solid_model_check.c. */
int solid_model_traits_check(const fsi_case *c, const char *role,
                             const solid_model_traits *t, FILE *errors);

#endif
