/* The classical fourth-order Runge-Kutta step of the solid (solid_rk4.h). */
#include "solid_rk4.h"

#include <stdlib.h>
#include <string.h>

int solid_rk4_init(solid_rk4_state *s, int n)
{
    const size_t size = (size_t)(n > 0 ? n : 1) * FSI_DIM * sizeof(double);
    s->n = n;
    s->x_n = malloc(size);
    s->v_n = malloc(size);
    s->dx = malloc(size);
    s->dv = malloc(size);
    if (!s->x_n || !s->v_n || !s->dx || !s->dv) {
        solid_rk4_free(s);
        return -1;
    }
    return 0;
}

void solid_rk4_free(solid_rk4_state *s)
{
    free(s->x_n);
    free(s->v_n);
    free(s->dx);
    free(s->dv);
    memset(s, 0, sizeof *s);
}

/* Adds weight * (k_x, k_v) of the stage the particles hold (k_x = v, k_v = a) to the
 * sums, then moves the particles to x_n + c k (the next stage's state) or, for the
 * last stage (combine), to x_n + c sum (the step's result); clamped points held at x0
 * and rest, mirrored ones following their partners. */
static void accumulate_and_move(solid_particles *p, solid_rk4_state *s, double weight,
                                double c, int combine)
{
    for (int i = 0; i < p->n; i++) {
        const int clamped = (p->flags[i] & SOLID_CLAMPED) != 0;
        for (int d = 0; d < FSI_DIM; d++) {
            const int k = i * FSI_DIM + d;
            const double kx = p->v[k], kv = p->a[k];
            s->dx[k] += weight * kx;
            s->dv[k] += weight * kv;
            if (clamped) {
                p->x[k] = p->x0[k];
                p->v[k] = 0.0;
                continue;
            }
            p->x[k] = s->x_n[k] + c * (combine ? s->dx[k] : kx);
            p->v[k] = s->v_n[k] + c * (combine ? s->dv[k] : kv);
        }
    }
    solid_follow_partners(p);
}

int solid_rk4_step(solid_particles *p, double t, double h, const solid_integrator *in,
                   solid_rk4_state *s, const solid_forces *f, solid_rk4_forces forces,
                   void *ctx, double *x_prev, double *work, solid_fault *fault)
{
    const size_t size = (size_t)p->n * FSI_DIM * sizeof(double);
    memcpy(s->x_n, p->x, size);
    memcpy(s->v_n, p->v, size);
    memcpy(x_prev, p->x, size);
    memset(s->dx, 0, size);
    memset(s->dv, 0, size);
    /* Stage weights h/6 (1, 2, 2, 1); each stage's state is x_n + c k of the last. */
    static const double weight[4] = {1.0, 2.0, 2.0, 1.0};
    static const double offset[3] = {0.5, 0.5, 1.0};
    fault->particle = -1;
    fault->what[0] = '\0';
    for (int stage = 0; stage < 3; stage++) {
        accumulate_and_move(p, s, weight[stage], offset[stage] * h, 0);
        if (forces(ctx, p, t + offset[stage] * h) != 0)
            return -2;
        solid_acceleration(p, f, in);
    }
    accumulate_and_move(p, s, weight[3], h / 6.0, 1);
    if (forces(ctx, p, t + h) != 0)
        return -2;
    solid_acceleration(p, f, in);
    return solid_step_end(p, f, h, in, x_prev, work, fault);
}
