/* Key table of the [run] section, owned by the coupler. */
#ifndef FSI_RUN_KEYS_H
#define FSI_RUN_KEYS_H

#include "case_file.h"

extern const fsi_key_table fsi_run_key_table;

/* Checks between [run] keys that single-key bounds cannot express (a validated
 * case); prints "FILE:LINE: [run] key: message" and returns the error count. */
int fsi_run_keys_check(const fsi_case *c, FILE *errors);

#endif
