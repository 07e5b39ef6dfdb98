/* The Verlet scheme of Monaghan (1989) as DualSPHysics uses it (Crespo et al. 2015,
 * §3.3): one evaluation of the rates per step, against two for the predictor-corrector
 * (wc_predictor_corrector.h), for weakly compressible schemes that can take it. With
 * the rates F^n, R^n at the step's start,
 *
 *     v^{n+1}   = v^{n-1} + (dt_{n-1} + dt_n) F^n
 *     x^{n+1}   = x^n + dt_n v^n + dt_n^2 / 2 F^n
 *     rho^{n+1} = rho^{n-1} + (dt_{n-1} + dt_n) R^n
 *
 * (the leapfrog over two steps; dt_{n-1} + dt_n is 2 dt of the constant-step form),
 * and every euler_interval-th step and the first one, the same with v^n and rho^n for
 * v^{n-1}, rho^{n-1} and dt_n for the sum, which ties the even and odd sequences
 * together again (DualSPHysics: every 40 steps). When the main loop permutes the
 * particles, v^{n-1} and rho^{n-1} are permuted with them and the sequence goes on:
 * sorting changes only the order of sums. Only fluid particles move. */
#ifndef FSI_WC_VERLET_H
#define FSI_WC_VERLET_H

#include "fluid_scheme.h"
#include "state_store.h"

/* DualSPHysics' default VerletSteps. */
#define FLUID_VERLET_EULER_INTERVAL 40

typedef struct {
    double *v_prev, *rho_prev;  /* v^{n-1}, rho^{n-1} of the fluid particles */
    double dt_prev;             /* dt_{n-1} [s] */
    long step;                  /* steps since the last restart of the sequence */
    long euler_interval;        /* see above; 1: every step is the Euler step */
    int capacity, have_prev;
} fluid_wc_verlet;

/* Empty, with the given interval (at least 1). */
void fluid_wc_verlet_init(fluid_wc_verlet *in, long euler_interval);

/* The next step restarts the sequence (the state of v^{n-1}, rho^{n-1} no longer
 * belongs to the step's start: e.g. after a density filter). */
void fluid_wc_verlet_restart(fluid_wc_verlet *in);

/* The first n particles were permuted: row k is now old row sorted[k] (scratch holds
 * n * FSI_DIM doubles). */
void fluid_wc_verlet_permute(fluid_wc_verlet *in, const int *sorted, int n, void *scratch);

/* One step of dt from time t with the start rates in hooks->drho, hooks->accel; calls
 * hooks->loads with dt (the loads of the step are those of its start). 0, or -1
 * (memory: msg; a hook: the owner's message). */
int fluid_wc_verlet_step(fluid_wc_verlet *in, fluid_particles *p, double t, double dt,
                         const fluid_step_hooks *hooks, char *msg, size_t msg_size);

/* The integrator's state between steps (v^{n-1}, rho^{n-1} of the first n particles,
 * dt_{n-1}, the step count of the sequence) under "<prefix>.*", and back. 0, or -1
 * (memory; no such state). */
int fluid_wc_verlet_save(const fluid_wc_verlet *in, int n, fsi_state *st, const char *prefix);
int fluid_wc_verlet_restore(fluid_wc_verlet *in, const fsi_state *st, const char *prefix);

void fluid_wc_verlet_free(fluid_wc_verlet *in);

#endif
