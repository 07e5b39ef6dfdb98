/* Key table of the [run] section, owned by the coupler. */
#ifndef FSI_RUN_KEYS_H
#define FSI_RUN_KEYS_H

#include "case_file.h"

extern const fsi_key_table fsi_run_key_table;

#endif
