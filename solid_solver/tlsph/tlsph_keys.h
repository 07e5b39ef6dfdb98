/* The case keys of the total-Lagrangian SPH solid ([solid.tlsph], solver = tlsph),
 * defined in tlsph_keys.c (library fsi_solid_keys, which the launcher's registry
 * links). */
#ifndef TLSPH_KEYS_H
#define TLSPH_KEYS_H

#include "case_file.h"

/* kernel, smoothing_length_factor, gradient_order, courant_number, hourglass_control. */
extern const fsi_key_table fsi_tlsph_keys;

/* Defaults, shared with solid_model_create's fallbacks for unvalidated cases. */
#define TLSPH_DEFAULT_H_FACTOR 1.2      /* 003 §2.1: h = 1.2 dx */
#define TLSPH_DEFAULT_COURANT 0.5
#define TLSPH_DEFAULT_HOURGLASS 0.0
#define TLSPH_DEFAULT_GRADIENT_ORDER 2  /* 1 is 003 Eq. 35 (docs/tlsph.md) */

#endif
