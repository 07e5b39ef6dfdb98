/* The solid's side of the interface exchange: gather the state of the particles the
 * fluid can reach (solid_model_surface) into contiguous buffers for
 * fsi_write_interface, and take the fluid's loads back by id.
 *
 * Ids are the particle indices (solid_particles.id[i] == i: particles are never
 * reordered or reallocated), so a load's id addresses its particle directly. A load
 * for an id that was not sent in this window, a duplicate or a value that is not
 * finite is an error: the fluid computed it from state it should not have.
 *
 * Ownership: the buffers own their arrays (solid_interface_free). */
#ifndef FSI_SOLID_INTERFACE_H
#define FSI_SOLID_INTERFACE_H

#include <stddef.h>
#include <stdint.h>

#include "participant.h"
#include "solid_particles.h"

typedef struct {
    int capacity;               /* particles the arrays hold (all of them) */
    uint8_t *surface;           /* per particle: 1 = sent this window */
    uint8_t *received;          /* per particle: a load arrived (duplicate check) */
    fsi_interface state;        /* what is published: n, id, position, velocity,
                                 * acceleration, volume (pressure, force NULL) */
} solid_interface_buffers;

int solid_interface_init(solid_interface_buffers *b, int n_particles);
void solid_interface_free(solid_interface_buffers *b);

/* Copies the particles with b->surface[i] set into b->state; returns its n. */
int solid_interface_gather(solid_interface_buffers *b, const solid_particles *p);

/* Takes the fluid's loads: force (n_particles * FSI_DIM) and pressure (n_particles)
 * are zeroed, then set for every id in 'in'. Returns 0, or -1 with a message naming
 * the first offending id. */
int solid_interface_take(solid_interface_buffers *b, const fsi_interface *in,
                         const solid_particles *p, double *force, double *pressure, char *msg,
                         size_t msg_size);

#endif
