/* The solid's side of implicit coupling, inside the participant library
 * (docs/coupling.md, Implicit coupling): the motion given to the fluid in each
 * iteration of a window, the residuals of the motion the solid then made, the verdict,
 * and the acceleration (core/coupling_acceleration.h) that picks the next motion.
 *
 * The unknown of the window's fixed point is every interface particle's window-mean
 * velocity u (its displacement over the window divided by dt). The fluid is given
 * the motion x(tau) = x_k + v tau + a tau^2 / 2 with
 *     a = 2 (u - u_prev) / (dt + dt_prev),   v = u - a dt / 2,
 * so that it ends the window where u says, and its acceleration is the change of
 * the window-mean velocities between the two windows' midpoints (as the explicit
 * scheme sends it; docs/coupling.md, The solid's motion as the fluid sees it). u_prev is
 * the mean velocity of the previous window, which the solid sends as its velocity.
 * The first iteration's u is the explicit scheme's prediction u_prev + a_k dt / 2 with
 * the acceleration a_k the solid sent.
 *
 * Ownership: the struct owns its arrays and the acceleration. */
#ifndef FSI_PARTICIPANT_IMPLICIT_H
#define FSI_PARTICIPANT_IMPLICIT_H

#include <stddef.h>
#include <stdint.h>

#include "case_file.h"
#include "coupling_acceleration.h"
#include "participant.h"

typedef struct {
    int converged;                  /* 1 / 0 */
    double displacement_residual;   /* |u_out - u_in| / |u_out| (displacements alike) */
    double force_residual;          /* |F_i - F_{i-1}| / |F_i|; 0 in iteration 0 */
    int history_columns, history_restarted;
} implicit_verdict;

typedef struct {
    fsi_accel *accel;
    double tolerance, absolute_tolerance;   /* [run] coupling_tolerance, ..._absolute_... */
    int repeat_motion;      /* test switch FSI_TEST_REPEAT_MOTION: every iteration gets
                             * the first one's motion (save/restore must then make the
                             * iterations identical) */
    int n, capacity;
    int iteration;          /* of the motion in u_in */
    double dt;              /* the window's length */
    double history_dt[2];   /* the lengths of the window the acceleration's history is of
                             * and of the window before it */
    int32_t *id;            /* the window's particles, in the order sent */
    double *x_start;        /* their positions at t_k */
    double *u_prev;         /* the last window's mean velocities (sent as velocity) */
    double *u_in, *u_out, *u_next;      /* this iteration's, its result, the next one's */
    double *v_sent, *a_sent;            /* the motion published for u_in */
    double *force, *force_last;         /* the fluid's loads, in sent order */
    int have_force_last;
    int restarted;          /* the acceleration dropped its history this window */
    implicit_verdict verdict;
} implicit_solid;

/* Reads [run] coupling_* of c. 0, or -1 with msg. */
int implicit_solid_init(implicit_solid *s, const fsi_case *c, char *msg, size_t msg_size);
void implicit_solid_free(implicit_solid *s);

/* The motion to publish in iteration `iteration` of a window of length dt that follows
 * one of length dt_prev, for the solid's state d at t_k; fills s->v_sent, s->a_sent.
 * Iteration 0 starts the window; later ones need the same particles in the same order
 * (a restored state), else -1 with msg. */
int implicit_solid_motion(implicit_solid *s, int iteration, double dt, double dt_prev,
                          const fsi_interface *d, char *msg, size_t msg_size);

/* The fluid's force on the k-th particle sent (k in sent order), n * FSI_DIM values. */
void implicit_solid_set_force(implicit_solid *s, int k, const double *force);

/* The solid's positions at the window's end: the residuals, the verdict and the next
 * iteration's motion. 0, or -1 with msg (other particles than sent, memory). */
int implicit_solid_window_end(implicit_solid *s, const fsi_interface *end, char *msg,
                              size_t msg_size);

/* The coupler accepted the window: its secant pairs join the history. */
void implicit_solid_accept(implicit_solid *s);

#endif
