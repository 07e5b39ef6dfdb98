/* The predictor-corrector every weakly compressible scheme steps with (000 Eq. 56;
 * WCSPH of 004 §2 uses the same): a scheme's fluid_scheme_step calls
 * fluid_wc_step with its own fluid_wc_integrator.
 *
 *   predictor  rho^{n+1/2} = rho^n + dt/2 drho^n,  v^{n+1/2} = v^n + dt/2 a^n,
 *              x^{n+1/2} = x^n + dt/2 v^n
 *   corrector  rho^{n+1} = rho^n + dt drho^{n+1/2},  v^{n+1} = v^n + dt a^{n+1/2},
 *              x^{n+1} = x^n + dt (v^n + v^{n+1}) / 2
 *
 * (000 Eq. 56 as printed is garbled; the corrector's position update uses the mean
 * velocity over the step, i.e. the corrected mid-step velocity, which keeps the scheme
 * second order.) Only fluid particles move; walls and the moving boundary are put
 * where they belong by the main loop's evaluate hook. */
#ifndef FSI_WC_PREDICTOR_CORRECTOR_H
#define FSI_WC_PREDICTOR_CORRECTOR_H

#include "fluid_scheme.h"

/* The state at the start of a step, sized to the particles (grows, never shrinks). */
typedef struct {
    double *x0, *v0, *rho0;
    int capacity;
} fluid_wc_integrator;

/* One step of dt from time t with the start rates in hooks->drho, hooks->accel:
 * the predictor, the evaluation at t + dt/2 (hooks->evaluate), hooks->loads, the
 * corrector. 0, or -1 (memory: msg; an evaluation: the owner's message). */
int fluid_wc_step(fluid_wc_integrator *in, fluid_particles *p, double t, double dt,
                  const fluid_step_hooks *hooks, char *msg, size_t msg_size);

void fluid_wc_integrator_free(fluid_wc_integrator *in);

#endif
