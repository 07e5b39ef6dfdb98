/* The Verlet scheme (wc_verlet.h). */
#include "wc_verlet.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fluid_parallel.h"
#include "fluid_state.h"
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
    const size_t cap = fsi_grown_capacity((size_t)n), old = (size_t)in->capacity;
    int failed = 0;
    in->v_prev = fsi_grow(in->v_prev, cap * FSI_DIM * sizeof(double), &failed);
    in->rho_prev = fsi_grow(in->rho_prev, cap * sizeof(double), &failed);
    if (failed)
        return -1;
    /* Rows of other particles than fluid ones are never written: zero, so that the
     * saved state is defined byte for byte. */
    memset(in->v_prev + old * FSI_DIM, 0, (cap - old) * FSI_DIM * sizeof(double));
    memset(in->rho_prev + old, 0, (cap - old) * sizeof(double));
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

/* The scalars of the sequence (no padding: the state is compared byte for byte). */
typedef struct {
    double dt_prev;
    int64_t step, have_prev, n;
} verlet_header;

int fluid_wc_verlet_save(const fluid_wc_verlet *in, int n, fsi_state *st, const char *prefix)
{
    verlet_header h = {in->dt_prev, in->step, in->have_prev, 0};
    if (in->have_prev)
        h.n = n < in->capacity ? n : in->capacity;
    fluid_state_put(st, prefix, "header", &h, sizeof h);
    if (h.n > 0) {
        fluid_state_put(st, prefix, "v_prev", in->v_prev, (size_t)h.n * FSI_DIM * sizeof(double));
        fluid_state_put(st, prefix, "rho_prev", in->rho_prev, (size_t)h.n * sizeof(double));
    }
    return st->failed ? -1 : 0;
}

int fluid_wc_verlet_restore(fluid_wc_verlet *in, const fsi_state *st, const char *prefix)
{
    verlet_header h;
    if (fluid_state_get(st, prefix, "header", &h, sizeof h) != 0 || h.n < 0 || h.n > INT32_MAX)
        return -1;
    const int n = (int)h.n;
    if (n > 0 && (reserve(in, n) != 0 ||
                  fluid_state_get(st, prefix, "v_prev", in->v_prev,
                                  (size_t)n * FSI_DIM * sizeof(double)) != 0 ||
                  fluid_state_get(st, prefix, "rho_prev", in->rho_prev,
                                  (size_t)n * sizeof(double)) != 0))
        return -1;
    in->dt_prev = h.dt_prev;
    in->step = (long)h.step;
    in->have_prev = (int)h.have_prev;
    return 0;
}
