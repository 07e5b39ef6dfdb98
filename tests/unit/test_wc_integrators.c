/* The shared weakly compressible integrators (fluid_solver/integrators/): the
 * predictor-corrector of 000 Eq. 56 and the Verlet scheme of DualSPHysics, driven
 * through the same fluid_step_hooks the main loop lends them.
 *
 *   1. Constant acceleration and density rate over uneven steps: both integrate a
 *      parabola and a linear density exactly (to round-off, 1e-12 relative), and a
 *      wall particle does not move.
 *   2. A harmonic oscillator x'' = -w^2 x, x(0) = 1: both converge at second order
 *      (halving the step divides the error at w t = 2.5 pi, where x = cos(w t)
 *      crosses zero and shows the phase error, by 4; accepted 3.5-4.5). The Verlet
 *      pair of sequences alone is neutral; each Euler step multiplies the energy by
 *      1 + (w dt)^2 (explicit Euler), so with one every 40 steps the amplitude may grow
 *      at most by that factor's square root per Euler step, and must not decay by
 *      more than 2 % over 50 periods at w dt = 0.05 (in a fluid, viscosity damps the
 *      growth; DualSPHysics' interval).
 *   3. The hooks: the predictor-corrector evaluates once per step (at the midpoint),
 *      Verlet never (the main loop evaluates at every step's start); both report the
 *      step's loads once per step. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "fluid_particles.h"
#include "fluid_scheme.h"
#include "wc_predictor_corrector.h"
#include "wc_verlet.h"

#include "unit_check.h"

static const double PI = 3.14159265358979323846;

typedef struct {
    fluid_particles *p;
    double drho[2], accel[2 * FSI_DIM];
    double omega2;              /* 0: constant acceleration g below */
    double g[FSI_DIM], rate;    /* constant acceleration and density rate */
    int evaluations, loads;
} oscillator;

static int evaluate(void *owner, double t)
{
    (void)t;
    oscillator *o = owner;
    for (int i = 0; i < o->p->n; i++) {
        o->drho[i] = o->rate;
        for (int d = 0; d < FSI_DIM; d++)
            o->accel[i * FSI_DIM + d] =
                o->omega2 > 0.0 ? -o->omega2 * o->p->x[i * FSI_DIM + d] : o->g[d];
    }
    o->evaluations++;
    return 0;
}

static int count_loads(void *owner, double dt)
{
    (void)dt;
    ((oscillator *)owner)->loads++;
    return 0;
}

enum { PREDICTOR_CORRECTOR, VERLET };

/* Integrates from t = 0 to t_end in steps of dt (dt2 for every other step when > 0);
 * returns the steps taken. */
static long run(int integrator, oscillator *o, double t_end, double dt, double dt2,
                long euler_interval)
{
    fluid_wc_integrator pc = {0};
    fluid_wc_verlet verlet;
    fluid_wc_verlet_init(&verlet, euler_interval);
    fluid_step_hooks hooks = {o, evaluate, count_loads, o->drho, o->accel, NULL, 0};
    char msg[256];
    double t = 0.0;
    long k = 0;
    evaluate(o, t);
    o->evaluations = 0;
    while (t < t_end - 1e-12 * t_end) {
        double h = (dt2 > 0.0 && k % 2) ? dt2 : dt;
        if (h > t_end - t)
            h = t_end - t;
        int rc = integrator == VERLET
                     ? fluid_wc_verlet_step(&verlet, o->p, t, h, &hooks, msg, sizeof msg)
                     : fluid_wc_step(&pc, o->p, t, h, &hooks, msg, sizeof msg);
        if (rc != 0) {
            CHECK(0, "step failed: %s", msg);
            break;
        }
        t += h;
        k++;
        if (integrator == VERLET) { /* the main loop's evaluation at the next start */
            const int e = o->evaluations;
            evaluate(o, t);
            o->evaluations = e;
        }
    }
    fluid_wc_integrator_free(&pc);
    fluid_wc_verlet_free(&verlet);
    return k;
}

static void set_up(fluid_particles *p, oscillator *o)
{
    memset(o, 0, sizeof *o);
    o->p = p;
    memset(p->x, 0, 2 * FSI_DIM * sizeof *p->x);
    memset(p->v, 0, 2 * FSI_DIM * sizeof *p->v);
    p->flags[0] = FLUID_PARTICLE_FLUID;
    p->flags[1] = FLUID_PARTICLE_WALL;
    p->x[0] = 1.0;
    p->x[FSI_DIM] = 0.5;
    p->v[1] = 0.3;
    p->density[0] = p->density[1] = 1000.0;
}

static void constant_rates(fluid_particles *p)
{
    const char *name[] = {"predictor-corrector", "Verlet"};
    for (int integrator = 0; integrator < 2; integrator++) {
        oscillator o;
        set_up(p, &o);
        o.g[0] = 0.7;
        o.g[1] = -9.81;
        o.rate = 3.0;
        const double t_end = 0.1;
        const long steps = run(integrator, &o, t_end, 1e-3, 2.5e-3, 5);
        const double x = 1.0 + 0.5 * o.g[0] * t_end * t_end;
        const double y = 0.3 * t_end + 0.5 * o.g[1] * t_end * t_end;
        const double err = fmax(fabs(p->x[0] - x) / fabs(x), fabs(p->x[1] - y) / fabs(y));
        const double err_v = fabs(p->v[1] - (0.3 + o.g[1] * t_end)) / fabs(0.3 + o.g[1] * t_end);
        const double err_rho = fabs(p->density[0] - (1000.0 + 3.0 * t_end)) / 1000.0;
        printf("%s, constant rates over %ld uneven steps: position %.2e, velocity %.2e, "
               "density %.2e relative error\n", name[integrator], steps, err, err_v, err_rho);
        CHECK(err < 1e-12 && err_v < 1e-12 && err_rho < 1e-12,
              "%s: constant acceleration not integrated exactly (x %.2e, v %.2e, rho %.2e)",
              name[integrator], err, err_v, err_rho);
        CHECK(p->x[FSI_DIM] == 0.5 && p->density[1] == 1000.0,
              "%s: the wall particle moved", name[integrator]);
        CHECK(o.loads == steps, "%s: loads reported %d times in %ld steps", name[integrator],
              o.loads, steps);
        CHECK(o.evaluations == (integrator == VERLET ? 0 : steps),
              "%s: %d evaluations inside %ld steps", name[integrator], o.evaluations, steps);
    }
}

/* |x(T) - cos(w T)| with w = 1, T = 2 pi periods, step dt. */
static double oscillator_error(int integrator, fluid_particles *p, double dt, long interval,
                               double periods, double *amplitude)
{
    oscillator o;
    set_up(p, &o);
    p->v[1] = 0.0;
    o.omega2 = 1.0;
    run(integrator, &o, 2.0 * PI * periods, dt, 0.0, interval);
    if (amplitude)
        *amplitude = sqrt(p->x[0] * p->x[0] + p->v[0] * p->v[0]);
    return fabs(p->x[0] - cos(2.0 * PI * periods));
}

static void second_order(fluid_particles *p)
{
    const char *name[] = {"predictor-corrector", "Verlet"};
    for (int integrator = 0; integrator < 2; integrator++) {
        const long interval = 1000000000L; /* only the first step is the Euler one */
        const double e1 = oscillator_error(integrator, p, 0.02, interval, 1.25, NULL);
        const double e2 = oscillator_error(integrator, p, 0.01, interval, 1.25, NULL);
        printf("%s, oscillator at w t = 2.5 pi: error %.3e at w dt = 0.02, %.3e at 0.01 "
               "(ratio %.2f)\n", name[integrator], e1, e2, e1 / e2);
        CHECK(e1 / e2 > 3.5 && e1 / e2 < 4.5, "%s: error ratio %.2f, not second order",
              name[integrator], e1 / e2);
    }
    double amplitude;
    const double dt = 0.05, periods = 50.0;
    oscillator_error(VERLET, p, dt, FLUID_VERLET_EULER_INTERVAL, periods, &amplitude);
    const double euler_steps = ceil(2.0 * PI * periods / dt / FLUID_VERLET_EULER_INTERVAL);
    const double bound = pow(1.0 + dt * dt, 0.5 * euler_steps);
    printf("Verlet, Euler step every %d: amplitude %.4f after 50 periods at w dt = 0.05 "
           "(bound %.4f from %.0f Euler steps)\n", FLUID_VERLET_EULER_INTERVAL, amplitude,
           bound, euler_steps);
    CHECK(amplitude > 0.98 && amplitude <= bound, "Verlet amplitude %.4f after 50 periods "
          "(bound %.4f)", amplitude, bound);
}

int main(void)
{
    fluid_particles p;
    if (fluid_particles_alloc(&p, 2, 0.01) != 0)
        return 1;
    constant_rates(&p);
    second_order(&p);
    fluid_particles_free(&p);
    return unit_check_report("test_wc_integrators");
}
