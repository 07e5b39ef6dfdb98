/* The fluid's global quantities over time: OUT/<participant>_diagnostics.csv, one row
 * per accepted window (docs/output.md, "Diagnostics"), written by the main loop every
 * fluid scheme shares (fluid_main.c), so every scheme writes the same columns; the one
 * scheme-dependent quantity, the compression energy, comes from the scheme's equation
 * of state (fluid_scheme_compression_energy; 0 for a projection scheme).
 *
 * The sums are O(N) once per window, serial so that a restarted run writes the same
 * digits as an uninterrupted one (a threaded reduction sums in another order). */
#ifndef FSI_FLUID_DIAGNOSTICS_H
#define FSI_FLUID_DIAGNOSTICS_H

#include <stddef.h>
#include <sys/types.h>

#include "fluid_particles.h"
#include "fluid_scheme.h"
#include "diagnostics_csv.h"

/* sum 1/2 m v^2 over the fluid particles [J, per unit thickness in 2D]. */
double fluid_kinetic_energy(const fluid_particles *p);
/* -sum m g . x over the fluid particles [J]: the gravity potential, zero at the
 * origin. */
double fluid_potential_energy(const fluid_particles *p, const double *gravity);
/* sum m e(rho) over the fluid particles, e the scheme's compression energy per mass
 * [J]. */
double fluid_compression_energy(const fluid_particles *p, const fluid_scheme *s);
/* Largest |v| of a fluid particle [m/s]. */
double fluid_max_speed(const fluid_particles *p);

/* One row: the state at the window's end and what the window took. */
typedef struct {
    int window;
    double dt;                  /* the window's length [s] */
    long steps;                 /* the fluid's steps in it */
    double step;                /* the last step's length [s] */
    double wall_work;           /* moving walls' work on the fluid so far [J] */
    double potential_wrapped;   /* the potential periodic wraps took away [J] */
    double interface_work;      /* the fluid's loads on the solid at the velocity the
                                 * solid sent, sum F . u dt so far [J] */
    double boundary_work;       /* the same over the boundary's own motion [J] */
    int inside;                 /* fluid particles inside the solid */
    double max_speed;           /* the fastest fluid particle's speed [m/s] (the one
                                 * the progress line was given) */
} fluid_window_summary;

typedef struct {
    fsi_diagnostics_csv file;
} fluid_diagnostics;

/* Creates DIR/NAME_diagnostics.csv with its header, or, with resume >= 0 (a restarted
 * run, docs/checkpoints.md), reopens it cut back to its first 'resume' bytes. 0, or -1
 * with msg. */
int fluid_diagnostics_open(fluid_diagnostics *d, const char *dir, const char *name,
                           off_t resume, char *msg, size_t msg_size);
/* Appends the row of the state at time t. 0, or -1 with msg (the file then still ends
 * at the last complete row). */
int fluid_diagnostics_write(fluid_diagnostics *d, double t, const fluid_particles *p,
                            const fluid_scheme *s, const double *gravity,
                            const fluid_window_summary *w, char *msg, size_t msg_size);
/* Bytes of complete rows so far (what a checkpoint keeps). */
off_t fluid_diagnostics_bytes(const fluid_diagnostics *d);
void fluid_diagnostics_close(fluid_diagnostics *d);

#endif
