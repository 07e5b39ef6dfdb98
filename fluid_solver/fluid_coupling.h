/* The fluid's side of the coupling (000 §3): the solid's interface particles become the
 * moving boundary particles of the fluid (fluid_boundary.h) at the start of every
 * window, and the force the fluid exerts on each of them over the window goes back to
 * the solid at its end (serial staggering, docs/protocol.md: the solid then advances
 * the same window with these loads).
 *
 * Loads: the force on a boundary particle is the exact reaction of the fluid's pair
 * terms (fluid_scheme_boundary_loads), averaged over the window as an impulse: each
 * step contributes h F(t_n + h/2), the midpoint rates that the predictor-corrector
 * (000 Eq. 56) advances the fluid with, so the solid receives exactly the momentum the
 * fluid lost to it. A window of length zero (window 0) sends the force at its instant.
 * The pressure sent is the boundary particle's interpolated pressure (000 Eq. 52) at
 * the last evaluation of the window. */
#ifndef FSI_FLUID_COUPLING_H
#define FSI_FLUID_COUPLING_H

#include <stddef.h>
#include <stdint.h>

#include "fluid_boundary.h"
#include "neighbour_grid.h"
#include "fluid_particles.h"
#include "fluid_scheme.h"
#include "participant.h"
#include "state_store.h"

typedef struct {
    fluid_boundary boundary;
    double t_window;            /* start of the current window [s] */
    double *impulse;            /* per boundary particle, FSI_DIM each: sum h F so far */
    double *force;              /* scratch, every particle, FSI_DIM each */
    int force_capacity, impulse_capacity;
    /* What fluid_coupling_publish sends. */
    int32_t *out_id;
    double *out_force, *out_pressure;
    int out_capacity;
    int n_windows;              /* windows with a boundary */
    double impedance;           /* rho0 c0 [Pa s/m] */
    double work_on_fluid;       /* work of the solid's particles on the fluid so far [J]:
                                 * sum of h (-F) . v at the steps' midpoints */
    double work_at_sent;        /* sum of h F . u over the steps [J], u the velocity the
                                 * solid sent for the window (the boundary's own velocity
                                 * adds the sent acceleration's a tau): what the solid's
                                 * loads do at the velocity it sent */
    double impulse_sent[FSI_DIM];   /* sum h F over all boundary particles and steps
                                     * [N s], summed from the forces themselves, not from
                                     * 'impulse': the solid's total of what it received
                                     * must equal it (tests/system/test_coupled_plate.sh) */
    double density_min, density_max;    /* the solid's density as received, least and
                                         * greatest over every particle of every window
                                         * [kg/m^3] (+-inf before any): logged, for the
                                         * solid's log of what it sent */
    fsi_neighbour_grid solid_grid;  /* the boundary particles, for the penetration check */
} fluid_coupling;

/* An empty coupling behind the n_fixed fluid and wall particles of the case, for a
 * fluid of acoustic impedance rho0 c0 [Pa s/m] (sent with the loads). */
void fluid_coupling_init(fluid_coupling *c, int n_fixed, double impedance);
void fluid_coupling_free(fluid_coupling *c);

/* The coupling's totals over the run under "<prefix>.*" (the main loop's state,
 * fluid_main.c): windows with a boundary, the work and impulse sent, the density range
 * received. Not the boundary itself nor the window's impulse: the start of every
 * window replaces them (fluid_coupling_receive), and a restore is always followed by
 * one. 0, or -1 (memory; restore: no such state). */
int fluid_coupling_save_state(const fluid_coupling *c, fsi_state *st, const char *prefix);
int fluid_coupling_restore_state(fluid_coupling *c, const fsi_state *st, const char *prefix);

/* Start of window [t0, ...]: reads the solid's state at t0 and puts its particles in
 * the tail of p. Returns 0, or -1 with msg. p->n may change. */
int fluid_coupling_receive(fluid_coupling *c, fsi_participant *part, fluid_particles *p,
                           double rho0, double t0, char *msg, size_t msg_size);

/* fluid_coupling_receive without the bus: starts the window at t0 with the solid's
 * state 'solid' (its particles into the tail of p, the impulse zeroed). */
int fluid_coupling_start_window(fluid_coupling *c, fluid_particles *p,
                                const fsi_interface *solid, double rho0, double t0,
                                char *msg, size_t msg_size);

/* The boundary particles at time t of the current window. */
void fluid_coupling_move(const fluid_coupling *c, fluid_particles *p, double t);

/* After the rates at a step's midpoint: adds h F to the window's impulse and the
 * work the solid did on the fluid to work_on_fluid. 0, or -1 when memory runs out. */
int fluid_coupling_accumulate(fluid_coupling *c, const fluid_scheme *scheme,
                              const fluid_particles *p, double h);

/* fluid_coupling_accumulate's arithmetic, for the forces force[p->n * FSI_DIM] on every
 * particle (the boundary tail is used) over a step of length h. */
void fluid_coupling_add_loads(fluid_coupling *c, const fluid_particles *p,
                              const double *force, double h);

/* The loads fluid_coupling_publish sends, into out_id, out_pressure and out_force: the
 * window's mean force impulse / dt on every boundary particle (dt > 0), else the
 * forces of the last fluid_coupling_accumulate's evaluation (c->force). 0, or -1 when
 * memory runs out. */
int fluid_coupling_window_loads(fluid_coupling *c, const fluid_particles *p, double dt);

/* End of a window of length dt: publishes its mean loads on every particle the solid
 * sent, in the order it sent them. 0, or -1 with msg. */
int fluid_coupling_publish(fluid_coupling *c, fsi_participant *part,
                           const fluid_scheme *scheme, const fluid_particles *p, double dt,
                           char *msg, size_t msg_size);

/* The fluid particles inside the solid: closer to one of its particles than half that
 * particle's own spacing, V^(1/DIM) / 2 (the solid's face lies there; a fluid particle
 * at rest on it sits (dx + dx_solid) / 2 from the nearest solid particle, so a solid
 * finer than the fluid is judged by its own spacing). Returns how many, or -1 when
 * memory runs out; *first is the index of one of them (-1 if none). */
int fluid_coupling_count_inside(fluid_coupling *c, const fluid_particles *p, int *first);

#endif
