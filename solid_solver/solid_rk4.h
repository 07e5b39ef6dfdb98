/* The classical fourth-order Runge-Kutta step of the solid (003 Eqs. 43-45), the
 * alternative to velocity Verlet (solid_integrate.h) for models whose internal force
 * is a function of the positions alone (solid_model_stateless): it evaluates the
 * forces at three trial states per step that it then throws away.
 *
 * One step of length h from (x_n, v_n, t_n), a(x, v, t) = F(x, t) / m + g - c v:
 *     k1 = (v_n,              a(x_n, v_n, t_n))             the last step's end
 *     k2 = (v_n + h/2 k1v,    a(x_n + h/2 k1x, ..., t_n + h/2))
 *     k3 = (v_n + h/2 k2v,    a(x_n + h/2 k2x, ..., t_n + h/2))
 *     k4 = (v_n + h k3v,      a(x_n + h k3x,  ..., t_n + h))
 *     (x, v)_{n+1} = (x, v)_n + h/6 (k1 + 2 k2 + 2 k3 + k4)
 * then a_{n+1} at the new state, which is also k1 of the next step (four force
 * evaluations a step). 003 prints the stage velocities without v_n (k_r2 = k_u1 dt/2,
 * ...): that is not a consistent scheme (a body moving at constant speed would stop),
 * so the stage velocities are v_n + the stage's increment, as in every RK4.
 * Clamped points stay at x0 with v = a = 0 in every stage; mirrored points follow
 * their partners in every stage. The damping term is explicit here: the step must
 * keep c h below RK4's real-axis stability bound 2.78 (the caller bounds h). */
#ifndef FSI_SOLID_RK4_H
#define FSI_SOLID_RK4_H

#include "solid_integrate.h"

/* Largest c h (damping times step) the explicit damping of RK4 is given: RK4 is
 * stable for real negative eigenvalues down to -2.78; 2 keeps a margin. */
#define SOLID_RK4_MAX_DAMPING_STEP 2.0

/* Computes the forces at the state the particles hold (x, v) at time t into the
 * arrays of the step's solid_forces (internal, with mirrored points' forces already
 * handed to their partners, and external), which the caller owns. Returns 0, or -1
 * with the caller's message set. */
typedef int (*solid_rk4_forces)(void *ctx, solid_particles *p, double t);

typedef struct {
    int n;
    double *x_n, *v_n;          /* state at the start of the step */
    double *dx, *dv;            /* sum of the weighted stages */
} solid_rk4_state;

/* Buffers for n particles; 0, or -1 when memory runs out. */
int solid_rk4_init(solid_rk4_state *s, int n);
void solid_rk4_free(solid_rk4_state *s);

/* One step of length h from t: on entry p->a holds k1v (the acceleration at the
 * particles' state with the forces at t) and f->external_prev the external forces at
 * t; on return p holds (x, v, a)_{n+1}, f's arrays the forces at t + h and x_prev the
 * positions at t. Checks
 * every point as solid_verlet_kick does (finite, moved at most max_step) and adds
 * the external forces' work (the same trapezoidal rule) to *work. Returns 0, -1 with
 * *fault set (integration), or -2 when 'forces' failed (its message stands). */
int solid_rk4_step(solid_particles *p, double t, double h, const solid_integrator *in,
                   solid_rk4_state *s, const solid_forces *f, solid_rk4_forces forces,
                   void *ctx, double *x_prev, double *work, solid_fault *fault);

#endif
