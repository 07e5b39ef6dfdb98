/* The keys of the ULPH scheme in [fluid] (solver = ulph). */
#ifndef ULPH_KEYS_H
#define ULPH_KEYS_H

#include "case_file.h"

extern const fsi_key_table fsi_ulph_keys;

#endif
