/* Probes of the solid ([solid.probe NAME] point = ...): each follows the particle
 * nearest to its point in the reference configuration and records, every window,
 * its displacement and velocity as probes.csv columns NAME_ux, NAME_uy (, NAME_uz),
 * NAME_vx, NAME_vy (, NAME_vz).
 *
 * Ownership: solid_probes owns its arrays (solid_probes_free). */
#ifndef FSI_SOLID_PROBES_H
#define FSI_SOLID_PROBES_H

#include <stddef.h>
#include <stdint.h>

#include "geometry.h"
#include "participant.h"

typedef struct {
    int n;
    int32_t *particle;          /* index of the followed particle */
    /* fsi_add_probe indices: u components, then v components; -1 without columns */
    int (*column)[2 * FSI_DIM];
} solid_probes;

/* Finds each probe's particle (error when none lies within one spacing) and, when
 * 'part' is not NULL, declares its 2 * FSI_DIM columns (before the first
 * fsi_ongoing). Returns 0, or -1 with a message. */
int solid_probes_init(solid_probes *pr, const solid_geometry *g, const solid_particles *p,
                      fsi_participant *part, char *msg, size_t msg_size);

/* Sets every column from the current state. */
void solid_probes_set(const solid_probes *pr, const solid_particles *p, fsi_participant *part);

void solid_probes_free(solid_probes *pr);

#endif
