/* The case keys of the pseudo-spring SPH solid ([solid.pseudo_spring], solver =
 * pseudo_spring), defined in pseudo_spring_keys.c (library fsi_solid_keys, which the
 * launcher's registry links). */
#ifndef PSEUDO_SPRING_KEYS_H
#define PSEUDO_SPRING_KEYS_H

#include "case_file.h"

/* smoothing_length_factor, artificial_viscosity_alpha, artificial_viscosity_beta,
 * artificial_stress, artificial_stress_exponent, failure, failure_strain,
 * courant_number, hourglass_control. */
extern const fsi_key_table fsi_pseudo_spring_keys;

/* Defaults, shared with solid_model_create's fallbacks for unvalidated cases. */
#define PSEUDO_SPRING_DEFAULT_H_FACTOR 1.5      /* 004 §5.2: h / dp = 1.5 */
#define PSEUDO_SPRING_DEFAULT_VISC_ALPHA 1.0
#define PSEUDO_SPRING_DEFAULT_VISC_BETA 1.0
#define PSEUDO_SPRING_DEFAULT_ART_STRESS 0.3    /* 004 §5.2: gamma = 0.3 */
#define PSEUDO_SPRING_DEFAULT_FAILURE_STRAIN 0.05       /* 004 §5.5 */
#define PSEUDO_SPRING_DEFAULT_COURANT 0.4
#define PSEUDO_SPRING_DEFAULT_HOURGLASS 1.0     /* the material's own 2 G: not a fit */

#endif
