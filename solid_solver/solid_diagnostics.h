/* The solid's global quantities over time: OUT/<participant>_diagnostics.csv, one row
 * per accepted window (docs/output.md, "Diagnostics"), written by the main loop every
 * solid model shares (solid_main.c) through the models' common functions
 * (solid_model_strain_energy), so every model writes the same columns.
 *
 * Per block of the case ([solid.block NAME]) the fluid's load on it: the total force
 * and its moment about the origin (x the current positions), sum x x F; a moment about
 * another point c is M - c x F, and blocks that make one body add up. The sums are
 * O(N) once per window and serial, so that a restarted run writes the same digits. */
#ifndef FSI_SOLID_DIAGNOSTICS_H
#define FSI_SOLID_DIAGNOSTICS_H

#include <stddef.h>
#include <sys/types.h>

#include "geometry.h"
#include "diagnostics_csv.h"
#include "solid_particles.h"

/* One row: the state at the window's end and what the window took. */
typedef struct {
    int window;
    double dt;                  /* the window's length [s] */
    long substeps;              /* the solid's sub-steps in it */
    double kinetic, strain;     /* [J] */
    double external_work;       /* work of every external force and gravity so far [J]
                                 * (prescribed loads, the fluid's load and the interface
                                 * impedance; not mass-proportional damping) */
    double interface_work;      /* the fluid's loads over the solid's own motion so far,
                                 * sum F . (x - x_prev) over the sub-steps [J] */
    double interface_work_at_sent;  /* the same at the velocity sent to the fluid [J] */
    double impedance_work;      /* the interface impedance's work so far [J] */
    const double *fluid_force;  /* the fluid's load on every particle [N], n * FSI_DIM */
    double max_speed;           /* the fastest point's speed [m/s] (the one the
                                 * progress line was given) */
} solid_window_summary;

typedef struct {
    fsi_diagnostics_csv file;
    int n_blocks;
    double *block_sums;         /* per block: force, moment */
} solid_diagnostics;

/* Creates DIR/NAME_diagnostics.csv with its header (a force and moment column group per
 * block of g), or, with resume >= 0 (a restarted run, docs/checkpoints.md), reopens it
 * cut back to its first 'resume' bytes. 0, or -1 with msg. */
int solid_diagnostics_open(solid_diagnostics *d, const solid_geometry *g, const char *dir,
                           const char *name, off_t resume, char *msg, size_t msg_size);
/* Appends the row of the state at time t. 0, or -1 with msg. */
int solid_diagnostics_write(solid_diagnostics *d, double t, const solid_particles *p,
                            const double *gravity, const solid_window_summary *w, char *msg,
                            size_t msg_size);
/* Bytes of complete rows so far (what a checkpoint keeps). */
off_t solid_diagnostics_bytes(const solid_diagnostics *d);
void solid_diagnostics_close(solid_diagnostics *d);

#endif
