/* Periodic boundaries of the fluid: [fluid] periodic = x | y | xy (3D also z, xz, yz,
 * xyz) with the period box periodic_min .. periodic_max (only the periodic axes'
 * components count). A particle leaving the box along a periodic axis re-enters at the
 * other end; pairs across the boundary interact through the nearest image
 * (core/periodic.h). */
#ifndef FSI_FLUID_PERIODIC_H
#define FSI_FLUID_PERIODIC_H

#include <stddef.h>

#include "case_file.h"
#include "periodic.h"

/* Reads the periodic keys of [role] into per (all axes off when periodic = none).
 * Returns 0, or -1 with msg naming the key (an unknown axis letter, max <= min). */
int fluid_periodic_read(const fsi_case *c, const char *role, fsi_periodic *per, char *msg,
                        size_t msg_size);

#endif
