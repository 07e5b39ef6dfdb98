/* What the fluid's output holds (docs/output.md): units, descriptions and flag names
 * of its static and frame fields, given to the writer before anything is written. */
#ifndef FSI_FLUID_OUTPUT_INFO_H
#define FSI_FLUID_OUTPUT_INFO_H

#include "h5_output.h"

/* The main loop's fields; the scheme's own come from fluid_scheme_describe_fields.
 * Returns 0, or -1 (fsi_h5_last_error). */
int fluid_output_describe(fsi_h5_writer *out);

#endif
