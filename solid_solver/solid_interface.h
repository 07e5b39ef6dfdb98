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

#include "case_file.h"
#include "participant.h"
#include "solid_particles.h"

typedef struct {
    int capacity;               /* particles the arrays hold (all of them) */
    uint8_t *surface;           /* per particle: 1 = sent this window */
    uint8_t *band;              /* per particle: 1 = within the interface depth of the
                                 * body's surface (solid_interface_band), always sent */
    double fluid_spacing;       /* the fluid's spacing [m] for the impedance area; 0: the
                                 * solid's (solid_interface_damping) */
    uint8_t *received;          /* per particle: a load arrived (duplicate check) */
    fsi_interface state;        /* what is published: n, id, position, velocity,
                                 * acceleration, volume, density (pressure, force
                                 * NULL) */
    /* Window means (solid_interface_gather): every particle's position at the last
     * window's start and its mean velocity over the window before, FSI_DIM each. */
    double *x_window, *v_mean;
    int have_x_window;          /* x_window holds a gather's positions */
    /* Per particle, FSI_DIM each (solid_interface_take): the window-mean velocity the
     * fluid moved it with over this window, the reference u of the impedance term
     * (solid_interface_damping): what the library hands back with the loads, or v_mean
     * when it hands back none. */
    double *u_fluid;
    double *end_position;       /* the sent particles' positions at the window's end
                                 * (solid_interface_window_end), FSI_DIM each */
    double dt_mean;             /* the window v_mean is over [s]; 0: no mean yet */
    double density_min, density_max;    /* the density sent, least and greatest over
                                         * every particle of every gather [kg/m^3]
                                         * (+-inf before any): logged, for the fluid's
                                         * log of what it received */
} solid_interface_buffers;

int solid_interface_init(solid_interface_buffers *b, int n_particles);
void solid_interface_free(solid_interface_buffers *b);

/* The depth [m] below the body's surface that the fluid of case c reaches
 * (docs/coupling.md, Unequal spacings): its support radius, which validation derives
 * from the fluid solver's own keys into [fluid] support (FSI_CASE_SUPPORT_KEY), less
 * half a fluid spacing, the gap its particles keep from a wall; 0 for a fluid without
 * one (an example or external fluid) or without a [fluid] section (their reach is
 * unknown: the model's surface set alone is sent). *fluid_spacing (may be NULL) gets
 * [fluid] spacing, 0 if none. */
double solid_interface_fluid_reach(const fsi_case *c, double *fluid_spacing);

/* The interface depth of case c's solid: [solid] interface_depth when given (> 0),
 * else solid_interface_fluid_reach. */
double solid_interface_depth(const fsi_case *c);

/* Marks b->band[i] = 1 for every particle within depth D of the body's surface in the
 * reference configuration x0, i.e. with fewer particles within D + dx/2 of it (dx
 * the spacing) than a full lattice has there: on a lattice a point at depth d below
 * a flat face has its nearest empty site d + dx/2 away. Mirrored clamp points fill
 * their sites (the fluid meets no surface there) but are never marked: they are
 * not material. D = 0 marks nothing. Returns how many are marked, or -1 when memory
 * runs out. Once, at start-up: the band is fixed to the reference configuration. */
int solid_interface_band(solid_interface_buffers *b, const solid_particles *p, double depth);

/* Copies the particles with b->surface[i] or b->band[i] set into b->state at the start
 * of a window that follows one of length dt_last (0 for the first); returns its n.
 *
 * Position, volume (the reference one) and density (density[i], p->n values: the
 * model's, solid_model_density) are the particle's. Velocity and acceleration are the
 * means over the windows that ended now, not the instants: the fluid samples the solid
 * once per window, and the solid's particle modes are far faster than that (their
 * period is ~ 2 dx / c_solid, micro-seconds in a metal plate), so an instantaneous
 * sample is aliased noise that the fluid's boundary condition (000 Eqs. 50-52) would
 * turn into pressure noise and feed back as load. The mean velocity
 * (x_k - x_{k-1}) / dt_{k-1} is what carries the body to its next position; the mean
 * acceleration is the change of the last two mean velocities over the time between
 * their midpoints. Until a window has passed the instants are sent, and the
 * acceleration is 0 until two have (both lag the instant by half a window, which the
 * windows' brevity against the body's own modes makes harmless). */
int solid_interface_gather(solid_interface_buffers *b, const solid_particles *p,
                           const double *density, double dt_last);

/* Takes the fluid's loads: force (n_particles * FSI_DIM) and pressure (n_particles)
 * are zeroed, then set for every id in 'in'. b->u_fluid gets, for every id in 'in',
 * in->velocity's entry (the same order as in->id: the window-mean velocity the fluid
 * moved the particle with, the one sent in an explicit run) when in->velocity is not
 * NULL, else b->v_mean's, as every particle without a load does. Returns 0, or -1
 * with a message naming the first offending id. */
int solid_interface_take(solid_interface_buffers *b, const fsi_interface *in,
                         const solid_particles *p, double *force, double *pressure, char *msg,
                         size_t msg_size);

/* The positions at the window's end (now, t_k + dt) of exactly the particles the
 * last gather put into b->state, same ids in the same order, for
 * fsi_write_window_end: end gets n and id (b->state's) and position
 * (b->end_position); its other fields are NULL. */
void solid_interface_window_end(solid_interface_buffers *b, const solid_particles *p,
                                fsi_interface *end);

/* The fluid's answer within a window (docs/coupling.md). The fluid's load F_k is held
 * over the window while the solid sub-cycles, computed for the motion the solid sent,
 * at the mean velocity u of the window (b->u_fluid: the v_mean of the last window
 * that the solid sent, or the iteration's motion of an implicit run; and the mean
 * acceleration, whose
 * small part a_mean (t - t_k) is left out here: with one sub-step per window it is a
 * second difference of positions, and fed back through z it pumped the solid's
 * fastest mode). Where the solid departs from that motion the fluid would have pushed
 * back at once with its acoustic impedance z = rho0 c0: a wall moving into still water
 * at v raises the pressure by z v. The solid applies that answer itself,
 *     F(t) = F_k - z A (v(t) - u),
 * on every particle that carries a non-zero load, with A = dx^(dim-1) (dx / dx_f): the
 * face one particle presents, times its layer's share of a fluid spacing (dx_f =
 * b->fluid_spacing; the factor is 1 when that is 0). The fluid's load spreads over the
 * layers within its reach, about 3.6 dx_f deep: at equal spacings 3-4 layers each with
 * the face's z A, and with a finer solid each of its more, thinner layers gets its share,
 * so that the correction stays the same multiple of z whatever the solid's spacing.
 * Without it the held load lags the solid's motion by up to a window, and every mode that
 * turns by more than a quarter period within a window is pumped (the load works against
 * the velocity one window late): a plate's short bending waves grew without bound. The
 * term vanishes when the solid follows u, i.e. as the window shrinks, and only ever
 * removes energy. damping[i] = z A / m_i [1/s] (0 for
 * particles without a load); the integrator treats -c v implicitly and the main loop
 * adds m c u to the external force. */
void solid_interface_damping(const solid_interface_buffers *b, const solid_particles *p,
                             const double *force, double impedance, double *damping);

#endif
