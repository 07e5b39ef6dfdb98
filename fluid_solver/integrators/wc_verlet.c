/* The Verlet scheme (wc_verlet.h). */
#include "wc_verlet.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fluid_parallel.h"
#include "grow.h"
#include "permute_rows.h"

void fluid_wc_verlet_init(fluid_wc_verlet *in, long euler_interval)
{
    memset(in, 0, sizeof *in);
    in->euler_interval = euler_interval > 0 ? euler_interval : 1;
}

void fluid_wc_verlet_restart(fluid_wc_verlet *in)
{
    in->have_prev = 0;
}

void fluid_wc_verlet_permute(fluid_wc_verlet *in, const int *sorted, int n, void *scratch)
{
    if (!in->have_prev)
        return;
    fsi_permute_rows(in->v_prev, sorted, n, FSI_DIM * sizeof(double), scratch);
    fsi_permute_rows(in->rho_prev, sorted, n, sizeof(double), scratch);
}

void fluid_wc_verlet_free(fluid_wc_verlet *in)
{
    free(in->v_prev);
    free(in->rho_prev);
    fluid_wc_verlet_init(in, in->euler_interval);
}

/* Room for n particles, keeping what is there (fluid particles come first and keep
 * their indices when the moving boundary at the tail changes size). */
static int reserve(fluid_wc_verlet *in, int n)
{
    if (n <= in->capacity && in->v_prev)
        return 0;
    const size_t cap = fsi_grown_capacity((size_t)n);
    int failed = 0;
    in->v_prev = fsi_grow(in->v_prev, cap * FSI_DIM * sizeof(double), &failed);
    in->rho_prev = fsi_grow(in->rho_prev, cap * sizeof(double), &failed);
    if (failed)
        return -1;
    in->capacity = (int)cap;
    return 0;
}

int fluid_wc_verlet_step(fluid_wc_verlet *in, fluid_particles *p, double t, double dt,
                         const fluid_step_hooks *hooks, char *msg, size_t msg_size)
{
    (void)t;
    const int n = p->n;
    if (reserve(in, n) != 0) {
        snprintf(msg, msg_size, "out of memory for the step of %d particles", n);
        return -1;
    }
    /* The loads of this step are those of the rates it uses, the start's. */
    if (hooks->loads(hooks->owner, dt) != 0)
        return -1;
    if (hooks->timers)
        fsi_timer_start(hooks->timers, hooks->integrate_timer);
    const int euler = !in->have_prev || in->step % in->euler_interval == 0;
    const double span = euler ? dt : in->dt_prev + dt;
    const double *drho = hooks->drho, *accel = hooks->accel;
#pragma omp parallel for schedule(static) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        if (!(p->flags[i] & FLUID_PARTICLE_FLUID))
            continue;
        const double rho = p->density[i];
        p->density[i] = (euler ? rho : in->rho_prev[i]) + span * drho[i];
        in->rho_prev[i] = rho;
        for (int d = 0; d < FSI_DIM; d++) {
            const int k = i * FSI_DIM + d;
            const double v = p->v[k];
            p->x[k] += dt * v + 0.5 * dt * dt * accel[k];
            p->v[k] = (euler ? v : in->v_prev[k]) + span * accel[k];
            in->v_prev[k] = v;
        }
    }
    in->dt_prev = dt;
    in->step = in->have_prev ? in->step + 1 : 1;
    in->have_prev = 1;
    if (hooks->timers)
        fsi_timer_stop(hooks->timers, hooks->integrate_timer);
    return 0;
}
