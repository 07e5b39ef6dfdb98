/* Probes of the fluid: [fluid.probe NAME] point = x, y writes the column NAME_p of
 * probes.csv, the pressure at that point, or with quantity = elevation the column
 * NAME_eta, the free-surface elevation above it. With follow = WALL the point moves
 * with that wall's prescribed motion (a probe on a moving tank). */
#ifndef FSI_FLUID_PROBES_H
#define FSI_FLUID_PROBES_H

#include <stddef.h>

#include "fluid_geometry.h"
#include "fluid_particles.h"
#include "participant.h"

typedef struct {
    int n;
    double (*point)[FSI_DIM];   /* where the point is at t = 0 */
    int *column;
    int *elevation;
    const fluid_motion **follow;    /* NULL: fixed */
    double spacing;
} fluid_probes;

/* One column per probe of g. Returns 0, or -1 with a message. */
int fluid_probes_init(fluid_probes *pr, const fluid_geometry *g, fsi_participant *part,
                      char *msg, size_t msg_size);

/* At time t, each point moved by its wall's motion:
 *  - pressure: the nearest fluid particle's pressure carried to the point along its
 *    pressure gradient grad_p (000 Eq. 13), p_I + grad p_I . (x - x_I), exact for the
 *    linear hydrostatic field also on the wall, where the nearest particle is half a
 *    spacing away;
 *  - elevation: max y_I + dx / 2 - y_point over the fluid particles within one spacing
 *    dx of the point horizontally (y the last axis, up). A particle's centre lies half
 *    a spacing below the surface of the lattice it fills, so water at rest gives 0 on
 *    its surface; a band of 2 dx always holds some particles. Splashes above the
 *    surface count (the highest water, like a wave gauge touching the first drop).
 *    NAN when no fluid particle is in the band. */
void fluid_probes_set(const fluid_probes *pr, const fluid_particles *p, const double *grad_p,
                      double t, fsi_participant *part);

void fluid_probes_free(fluid_probes *pr);

#endif
