/* The interface every solid model folder implements (nosbpd/, later tlsph/,
 * pseudo_spring/), in the spirit of SWIFT's hydro schemes: the same small set of
 * functions, one model linked per executable (fsi-solid-<model>), chosen by the
 * case's `solver = <model>`. The main loop (solid_main.c) owns the particles, time
 * integration (velocity Verlet, 000 Eq. 55), external and interface loads, damping,
 * output and the coupling; the model owns everything between positions and internal
 * forces: bonds, kinematics, constitutive state, failure.
 *
 * Error convention: functions returning int give 0 on success and -1 after writing
 * one line "what, where (particle id and position), when (time)" to msg[msg_size]. */
#ifndef FSI_SOLID_MODEL_H
#define FSI_SOLID_MODEL_H

#include <stddef.h>

#include "case_file.h"
#include "h5_output.h"
#include "solid_particles.h"
#include "state_store.h"

typedef struct solid_model solid_model;

/* Case keys: each model folder also defines `const fsi_key_table fsi_<model>_keys`
 * in its own <model>_keys.c (distinct names, because the launcher's registry links
 * every model's keys at once while an executable links one model). */

/* Builds bonds and constitutive state for the particles in their reference
 * configuration x0. Warns on stderr about points whose horizon is too poor. */
solid_model *solid_model_create(const fsi_case *c, const solid_particles *p, char *msg,
                                size_t msg_size);

/* Largest stable explicit step for the current state [s], before the main loop's
 * safety factor. */
double solid_model_stable_dt(const solid_model *m, const solid_particles *p);

/* Internal force on every particle [N, per unit thickness in 2D] for the positions
 * p->x reached from x_prev over dt (the incremental, objective stress update needs
 * both), at time t (for messages). Updates stress, plastic state and bonds
 * (breaking is permanent). force has p->n * FSI_DIM entries, overwritten. */
int solid_model_internal_force(solid_model *m, const solid_particles *p, const double *x_prev,
                               double dt, double t, double *force, char *msg, size_t msg_size);

/* 1 when the internal force is a function of the positions alone and a call commits
 * nothing (total-Lagrangian models with a total-form material), so that a multi-stage
 * integrator (RK4) may evaluate it at trial states it then throws away; 0 for models
 * that commit state in every call (bonds that break, incremental stress, plastic
 * state), which only take velocity Verlet's one evaluation per step. */
int solid_model_stateless(const solid_model *m);

/* Marks (1) the particles whose horizon is cut by a free surface or a crack: the
 * points the fluid can reach. Returns how many. */
int solid_model_surface(const solid_model *m, const solid_particles *p, uint8_t *surface);

/* The density of every particle [kg/m^3] at the current positions, p->n values owned
 * by the model or p, for the fluid (the structure's inertia in its pressure equation,
 * solid_interface_gather): the model's current density where it integrates one
 * (pseudo-spring SPH, 004 Eq. 14), else the material's, p->density (NOSB-PD and TLSPH
 * are total-Lagrangian: mass per reference volume is all they keep). Valid until the
 * next internal-force call. */
const double *solid_model_density(const solid_model *m, const solid_particles *p);

/* Writes the model's fields (stress, damage, plastic strain, ...) into the open frame. */
int solid_model_write_fields(const solid_model *m, fsi_h5_writer *out);
/* Their units, descriptions and flag names (fsi_h5_describe), before the first frame. */
int solid_model_describe_fields(fsi_h5_writer *out);

/* The length h [m] of a kernel of support 2 h that covers a point's family: the
 * kernel's own h (TLSPH, pseudo-spring SPH), half the horizon (NOSB-PD). The output
 * gives it for ParaView's SPH interpolators (docs/output.md). */
double solid_model_smoothing_length(const solid_model *m);

/* Strain energy of the body [J, per unit thickness in 2D] for the energy check. */
double solid_model_strain_energy(const solid_model *m, const solid_particles *p);

/* The model's state (implicit coupling, docs/coupling.md: the main loop saves it at a
 * window's start and restores it when the coupler repeats the window; later also the
 * coupled checkpoints on disk). Save puts into st, without clearing it, everything
 * the internal-force calls have committed (broken bonds, stress, plastic state, ...),
 * as entries named "<model>.<array>"; restore brings the model back to exactly that
 * state, so that the same positions then give the same forces, fields and energy bit
 * for bit, and recomputes what it derives from it (shape tensors, damage, ...). What
 * every internal-force call rewrites before reading it is not saved. Restore works
 * on the model the state was saved from or on a fresh one created from the same case
 * and particles. Both return 0, or -1: save when memory runs out (st->failed),
 * restore when st lacks an entry or holds one of another size (then nothing is
 * changed). */
int solid_model_save_state(const solid_model *m, const solid_particles *p, fsi_state *st);
int solid_model_restore_state(solid_model *m, solid_particles *p, const fsi_state *st);

/* Pair interactions one internal-force call works through (for NOSB-PD the directed
 * bonds of the reference families): the unit of the performance figures in the log. */
int64_t solid_model_interaction_count(const solid_model *m);

void solid_model_free(solid_model *m);

#endif
