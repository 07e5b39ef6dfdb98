/* The weakly compressible predictor-corrector (wc_predictor_corrector.h). */
#include "wc_predictor_corrector.h"

#include "fluid_parallel.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grow.h"

static int reserve(fluid_wc_integrator *in, int n)
{
    if (n <= in->capacity && in->x0)
        return 0;
    /* No zeroing: every step writes these before it reads them. */
    const size_t cap = fsi_grown_capacity((size_t)n), vec = cap * FSI_DIM * sizeof(double);
    int failed = 0;
    in->x0 = fsi_grow(in->x0, vec, &failed);
    in->v0 = fsi_grow(in->v0, vec, &failed);
    in->rho0 = fsi_grow(in->rho0, cap * sizeof(double), &failed);
    if (failed)
        return -1;
    in->capacity = (int)cap;
    return 0;
}

void fluid_wc_integrator_free(fluid_wc_integrator *in)
{
    free(in->x0);
    free(in->v0);
    free(in->rho0);
    memset(in, 0, sizeof *in);
}

static void timer(const fluid_step_hooks *hooks, int start)
{
    if (!hooks->timers)
        return;
    if (start)
        fsi_timer_start(hooks->timers, hooks->integrate_timer);
    else
        fsi_timer_stop(hooks->timers, hooks->integrate_timer);
}

int fluid_wc_step(fluid_wc_integrator *in, fluid_particles *p, double t, double dt,
                  const fluid_step_hooks *hooks, char *msg, size_t msg_size)
{
    const int n = p->n;
    if (reserve(in, n) != 0) {
        snprintf(msg, msg_size, "out of memory for the step of %d particles", n);
        return -1;
    }
    timer(hooks, 1);
    const double *drho = hooks->drho, *accel = hooks->accel;
    memcpy(in->x0, p->x, (size_t)n * FSI_DIM * sizeof *p->x);
    memcpy(in->v0, p->v, (size_t)n * FSI_DIM * sizeof *p->v);
    memcpy(in->rho0, p->density, (size_t)n * sizeof *p->density);
#pragma omp parallel for schedule(static) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        if (!(p->flags[i] & FLUID_PARTICLE_FLUID))
            continue;
        p->density[i] += 0.5 * dt * drho[i];
        for (int d = 0; d < FSI_DIM; d++) {
            p->x[i * FSI_DIM + d] += 0.5 * dt * p->v[i * FSI_DIM + d];
            p->v[i * FSI_DIM + d] += 0.5 * dt * accel[i * FSI_DIM + d];
        }
    }
    timer(hooks, 0);
    if (hooks->evaluate(hooks->owner, t + 0.5 * dt) != 0 ||
        hooks->loads(hooks->owner, dt) != 0)
        return -1;
    timer(hooks, 1);
#pragma omp parallel for schedule(static) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        if (!(p->flags[i] & FLUID_PARTICLE_FLUID))
            continue;
        p->density[i] = in->rho0[i] + dt * drho[i];
        for (int d = 0; d < FSI_DIM; d++) {
            const int k = i * FSI_DIM + d;
            p->v[k] = in->v0[k] + dt * accel[k];
            p->x[k] = in->x0[k] + 0.5 * dt * (in->v0[k] + p->v[k]);
        }
    }
    timer(hooks, 0);
    return 0;
}
