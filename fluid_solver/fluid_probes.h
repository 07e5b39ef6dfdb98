/* Pressure probes of the fluid: [fluid.probe NAME] point = x, y writes the column
 * NAME_p of probes.csv, the pressure at that fixed point. */
#ifndef FSI_FLUID_PROBES_H
#define FSI_FLUID_PROBES_H

#include <stddef.h>

#include "fluid_geometry.h"
#include "fluid_particles.h"
#include "participant.h"

typedef struct {
    int n;
    double (*point)[FSI_DIM];
    int *column;
} fluid_probes;

/* One column per probe of g. Returns 0, or -1 with a message. */
int fluid_probes_init(fluid_probes *pr, const fluid_geometry *g, fsi_participant *part,
                      char *msg, size_t msg_size);

/* The pressure at each point: the nearest fluid particle's pressure carried to the
 * point along its pressure gradient grad_p (000 Eq. 13), p_I + grad p_I . (x - x_I),
 * exact for the linear hydrostatic field also on the wall, where the nearest
 * particle is half a spacing away. */
void fluid_probes_set(const fluid_probes *pr, const fluid_particles *p, const double *grad_p,
                      fsi_participant *part);

void fluid_probes_free(fluid_probes *pr);

#endif
