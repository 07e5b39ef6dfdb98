/* The solid's time integrators, driven through the real functions: velocity Verlet
 * (solid_verlet_drift, the forces, solid_verlet_kick; solid_integrate.h) and RK4
 * (solid_rk4_step with a force callback; solid_rk4.h), on independent linear springs
 * f = -k (x - x0) with a known solution:
 *  - convergence orders from the phase-space error at a fixed end time with steps h
 *    and h/2, against the exact harmonic solution: RK4's ratio about 16 (14-18
 *    accepted), Verlet's about 4 (3.6-4.4); with the integrators' damping
 *    (a = f/m - c v) against the exact damped oscillator, RK4 still about 16, Verlet
 *    (implicit damping) still about 4; each within its leading error term;
 *  - a clamped point (with a force on it, started displaced and moving) is at x0 with
 *    v = a = 0 after every step, and a mirrored clamp point follows its partner
 *    (x - x0 = -(x_m - x0_m), v = -v_m, a = -a_m) after every step of both
 *    integrators; the partner moves;
 *  - solid_step_end's work: a constant external force F (and gravity) on free masses
 *    adds exactly (F + m g) . (x_end - x_start) over many steps, to round-off; for a
 *    force growing as F1 t, RK4's motion is exact and the work booked is the
 *    trapezoidal rule's on it (the force at both ends of each step);
 *  - a non-finite force gives -1 and a fault at that particle, a step beyond max_step
 *    -1 with a fault saying how far, and a force callback that fails makes
 *    solid_rk4_step return -2.
 * The mirrored point has a spring of its own: the callback hands its force to the
 * partner as the main loop does (solid_mirror_forces), so by the chain rule
 * (u_g = -u_m) the partner moves as one spring of stiffness k_m + k_g. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "solid_integrate.h"
#include "solid_rk4.h"

#include "unit_check.h"
#include "unit_solid_lattice.h"

static const double PI = 3.14159265358979323846;
static const double DX = 0.01, RHO = 1000.0, END_TIME = 1.0;

/* Points of the spring system: FREE free springs, then a clamped point, then a
 * mirrored clamp point whose partner is free point PARTNER. */
enum { FREE = 4, CLAMPED = FREE, GHOST = FREE + 1, N_POINTS = FREE + 2, PARTNER = 1 };

typedef enum { VERLET, RK4 } scheme;

/* The force field of a run (the context of solid_rk4_forces). */
typedef struct {
    double k[N_POINTS];                     /* spring stiffness [N/m] */
    double f_const[N_POINTS * FSI_DIM];     /* constant external force [N] */
    double ramp[N_POINTS * FSI_DIM];        /* external force growing as ramp t [N/s] */
    double *internal, *external;            /* the arrays solid_forces points to */
    int fail;                               /* 1: the callback fails (a model error) */
    int poison;                             /* >= 0: this point's force is NaN */
} springs;

static int spring_forces(void *ctx, solid_particles *p, double t)
{
    springs *s = ctx;
    for (int i = 0; i < p->n; i++)
        for (int d = 0; d < FSI_DIM; d++) {
            const int k = i * FSI_DIM + d;
            s->internal[k] = -s->k[i] * (p->x[k] - p->x0[k]);
            s->external[k] = i == s->poison ? NAN : s->f_const[k] + s->ramp[k] * t;
        }
    solid_mirror_forces(p, s->internal);
    return s->fail ? -1 : 0;
}

static double mass(const solid_particles *p, int i)
{
    return p->density[i] * p->volume[i];
}

/* Angular frequencies 2 pi (1, 1.7, 2.6, 3.5) rad/s of the free springs (the partner's
 * with its image's spring added), initial displacements of a fraction of dx and
 * velocities of the same order times omega, in every direction. */
static const double FREQUENCY[FREE] = {1.0, 1.7, 2.6, 3.5};

static solid_particles *spring_system(springs *s)
{
    solid_particles *p = test_lattice(N_POINTS, 1, 1, DX, RHO);
    p->mirror = malloc((size_t)p->n * sizeof *p->mirror);
    memset(s, 0, sizeof *s);
    s->poison = -1;
    for (int i = 0; i < p->n; i++) {
        p->mirror[i] = -1;
        const double omega = 2.0 * PI * (i < FREE ? FREQUENCY[i] : 1.3);
        s->k[i] = mass(p, i) * omega * omega;
        for (int d = 0; d < FSI_DIM; d++) {
            const int k = i * FSI_DIM + d;
            if (i < FREE) {
                p->x[k] += (0.2 - 0.07 * d + 0.05 * i) * DX;
                p->v[k] = (0.1 + 0.03 * d - 0.04 * i) * DX * omega;
            }
        }
    }
    /* The partner is one spring of k_m + k_g (the header): keep its frequency. */
    s->k[PARTNER] -= s->k[GHOST];
    /* The clamped point starts displaced and moving, with a force on it: the first
     * step must put it back at x0 and at rest, and keep it there. */
    p->flags[CLAMPED] = SOLID_CLAMPED;
    for (int d = 0; d < FSI_DIM; d++) {
        s->f_const[CLAMPED * FSI_DIM + d] = 3.0 + d;
        p->x[CLAMPED * FSI_DIM + d] += 0.1 * DX;
        p->v[CLAMPED * FSI_DIM + d] = 0.05;
    }
    p->flags[GHOST] = SOLID_CLAMPED | SOLID_MIRRORED;
    p->mirror[GHOST] = PARTNER;
    /* A consistent start: the image displaced against its partner (else the first
     * force on the partner misses its image's spring, an O(h) error). */
    solid_follow_partners(p);
    return p;
}

/* Clamp and mirror after a step: 0 when they hold. The image's displacement is
 * formed as x0 - (x_m - x0_m), so it matches -(x_m - x0_m) to the round-off of
 * positions of 0.06 m: 4 eps |x0|. */
static int clamps_broken(const solid_particles *p)
{
    int bad = 0;
    for (int d = 0; d < FSI_DIM; d++) {
        const int c = CLAMPED * FSI_DIM + d, g = GHOST * FSI_DIM + d, m = PARTNER * FSI_DIM + d;
        bad |= p->x[c] != p->x0[c] || p->v[c] != 0.0 || p->a[c] != 0.0;
        bad |= fabs((p->x[g] - p->x0[g]) + (p->x[m] - p->x0[m])) > 4.0 * DBL_EPSILON * p->x0[g];
        bad |= p->v[g] != -p->v[m] || p->a[g] != -p->a[m];
    }
    return bad;
}

/* What a run of integrate() did. */
typedef struct {
    int status;         /* the last step's: 0, -1 (fault) or -2 (the callback failed) */
    int clamps;         /* steps after which a clamp or a mirror did not hold */
    double work;        /* the work bookkeeping's sum [J] */
    solid_fault fault;
} run_result;

/* 'steps' steps of END_TIME / steps from the particles' state, the way the main loop
 * runs a window (solid_main.c, advance): the acceleration at the start, then per step
 * the external forces of its start as external_prev. */
static run_result integrate(solid_particles *p, springs *s, scheme how, int steps,
                            const solid_integrator *in)
{
    const size_t size = (size_t)p->n * FSI_DIM * sizeof(double);
    double *internal = calloc(1, size), *ext[2] = {calloc(1, size), calloc(1, size)};
    double *x_prev = calloc(1, size);
    solid_rk4_state rk;
    run_result r = {0, 0, 0.0, {-1, ""}};
    if (solid_rk4_init(&rk, p->n) != 0)
        exit(2);
    const double h = END_TIME / steps;
    /* The start: forces and acceleration at t = 0 (the main loop's window start). */
    s->internal = internal;
    s->external = ext[0];
    solid_forces f = {internal, ext[0], ext[1]};
    spring_forces(s, p, 0.0);
    solid_acceleration(p, &f, in);
    for (int j = 0; j < steps && r.status == 0; j++) {
        /* The external forces at the step's start become external_prev (work). */
        double *swap = ext[0];
        ext[0] = ext[1];
        ext[1] = swap;
        f.external = s->external = ext[0];
        f.external_prev = ext[1];
        const double t = j * h;
        if (how == RK4) {
            r.status = solid_rk4_step(p, t, h, in, &rk, &f, spring_forces, s, x_prev, &r.work,
                                      &r.fault);
        } else {
            solid_verlet_drift(p, h, x_prev);
            if (spring_forces(s, p, t + h) != 0)
                r.status = -2;
            else
                r.status = solid_verlet_kick(p, &f, h, in, x_prev, &r.work, &r.fault);
        }
        r.clamps += clamps_broken(p);
    }
    solid_rk4_free(&rk);
    free(internal);
    free(ext[0]);
    free(ext[1]);
    free(x_prev);
    return r;
}

/* u(t) and u'(t) of u'' + c u' + omega^2 u = 0, u(0) = u0, u'(0) = v0, underdamped
 * (c < 2 omega): u = e^(-c t / 2) (u0 cos w t + (v0 + c u0 / 2) / w sin w t),
 * w = sqrt(omega^2 - c^2 / 4). */
static void oscillator(double omega, double c, double u0, double v0, double t, double *u,
                       double *v)
{
    const double lambda = 0.5 * c, w = sqrt(omega * omega - lambda * lambda);
    const double b = (v0 + lambda * u0) / w, e = exp(-lambda * t);
    const double cs = cos(w * t), sn = sin(w * t);
    *u = e * (u0 * cs + b * sn);
    *v = e * (-lambda * (u0 * cs + b * sn) + w * (-u0 * sn + b * cs));
}

/* Phase-space error |(x - x_exact, (v - v_exact) / omega)| of each free point at the
 * end time, over its initial amplitude |(u0, v0 / omega)|: a phase error shows at the
 * same size whatever the phase at the end (no chance zero of x alone). */
static void errors(scheme how, int steps, double c, double *err, int *clamps)
{
    springs s;
    solid_particles *p = spring_system(&s);
    double u0[N_POINTS * FSI_DIM], v0[N_POINTS * FSI_DIM];
    for (int k = 0; k < p->n * FSI_DIM; k++) {
        u0[k] = p->x[k] - p->x0[k];
        v0[k] = p->v[k];
    }
    solid_integrator in = {.damping = c, .max_step = 1.0};
    const run_result r = integrate(p, &s, how, steps, &in);
    CHECK(r.status == 0, "%s, %d steps: status %d (%s)", how == RK4 ? "RK4" : "Verlet", steps,
          r.status, r.fault.what);
    *clamps += r.clamps;
    for (int i = 0; i < FREE; i++) {
        const double omega = 2.0 * PI * FREQUENCY[i];
        double e2 = 0.0, a2 = 0.0;
        for (int d = 0; d < FSI_DIM; d++) {
            const int k = i * FSI_DIM + d;
            double u, v;
            oscillator(omega, c, u0[k], v0[k], END_TIME, &u, &v);
            e2 += pow(p->x[k] - p->x0[k] - u, 2) + pow((p->v[k] - v) / omega, 2);
            a2 += u0[k] * u0[k] + pow(v0[k] / omega, 2);
        }
        err[i] = sqrt(e2 / a2);
    }
    test_lattice_free(p);
}

/* The error ratio between steps END_TIME / n and END_TIME / 2n, for every free point,
 * in [low, high]; also the h/2 error below 'bound' (if positive). */
static void check_order(scheme how, int n, double c, double low, double high, double bound)
{
    double coarse[FREE], fine[FREE];
    int clamps = 0;
    errors(how, n, c, coarse, &clamps);
    errors(how, 2 * n, c, fine, &clamps);
    const char *name = how == RK4 ? "RK4" : "Verlet";
    double lo = INFINITY, hi = 0.0, worst = 0.0;
    for (int i = 0; i < FREE; i++) {
        const double ratio = coarse[i] / fine[i];
        lo = fmin(lo, ratio);
        hi = fmax(hi, ratio);
        worst = fmax(worst, fine[i]);
    }
    printf("%s, c = %g 1/s, %d and %d steps over %g s: error ratio %.3f to %.3f (want "
           "%.1f-%.1f), largest relative error %.3g at h/2\n",
           name, c, n, 2 * n, END_TIME, lo, hi, low, high, worst);
    CHECK(lo >= low && hi <= high, "%s, c = %g: error ratios %.3f to %.3f outside [%g, %g]",
          name, c, lo, hi, low, high);
    CHECK(bound <= 0.0 || worst < bound, "%s, c = %g: error %.3g above %.3g", name, c, worst,
          bound);
    CHECK(clamps == 0, "%s, c = %g: after %d steps a clamp or a mirror did not hold", name, c,
          clamps);
}

static void check_orders(void)
{
    /* RK4's error for u' = i omega u after n steps is n |z|^5 / 120, z = omega h (the
     * first term of e^z - R(z)): at the highest frequency 2 pi 3.5 rad/s and 200 steps,
     * omega T (omega h)^4 / 120 = 2.7e-5; 1e-4 bounds it with the damping's share. */
    check_order(RK4, 100, 0.0, 14.0, 18.0, 1e-4);
    check_order(RK4, 100, 1.5, 14.0, 18.0, 1e-4);
    /* Verlet's phase error after a time T is omega T (omega h)^2 / 24: 1.1e-2 at the
     * highest frequency and 200 steps; 2e-2 bounds it. */
    check_order(VERLET, 100, 0.0, 3.6, 4.4, 2e-2);
    check_order(VERLET, 100, 1.5, 3.6, 4.4, 2e-2);
}

/* The mirrored point's partner moves (the clamp checks are not about a point at
 * rest). */
static void check_partner_moves(void)
{
    springs s;
    solid_particles *p = spring_system(&s);
    solid_integrator in = {.max_step = 1.0};
    const run_result r = integrate(p, &s, RK4, 100, &in);
    double moved = 0.0;
    for (int d = 0; d < FSI_DIM; d++)
        moved = fmax(moved, fabs(p->x[GHOST * FSI_DIM + d] - p->x0[GHOST * FSI_DIM + d]));
    printf("mirrored point: displaced by %.3g dx at t = %g s\n", moved / DX, END_TIME);
    CHECK(r.status == 0 && moved > 0.01 * DX, "the mirrored point did not move (%g m)", moved);
    test_lattice_free(p);
}

/* The spring system with its springs removed: free masses, one (point 0) under a
 * constant force F across its initial velocity, all under gravity g in one variant,
 * for 50 steps. The trapezoidal work of every step is (F + m g) . dx for each point,
 * so the sum telescopes to sum (F + m g) . (x_end - x_start), to the round-off of 50
 * sums (1e-12 relative). The clamped point's force does no work, nor does gravity on
 * the image. */
static void check_work(void)
{
    for (int how = VERLET; how <= RK4; how++)
        for (int with_gravity = 0; with_gravity < 2; with_gravity++) {
            springs s;
            solid_particles *p = spring_system(&s);
            memset(s.k, 0, sizeof s.k);
            for (int d = 0; d < FSI_DIM; d++) {
                s.f_const[d] = 0.4 - 0.3 * d;
                p->v[d] = 0.2 * (d % 2 ? -1.0 : 1.0);
            }
            solid_integrator in = {.max_step = 1.0};
            if (with_gravity)
                in.gravity[1] = -9.81;
            double start[N_POINTS * FSI_DIM];
            memcpy(start, p->x, sizeof start);
            const run_result r = integrate(p, &s, (scheme)how, 50, &in);
            double expect = 0.0, scale = 0.0;
            for (int i = 0; i < p->n; i++)
                for (int d = 0; d < FSI_DIM && !(p->flags[i] & SOLID_CLAMPED); d++) {
                    const int k = i * FSI_DIM + d;
                    const double f = s.f_const[k] + mass(p, i) * in.gravity[d];
                    expect += f * (p->x[k] - start[k]);
                    scale += fabs(f * (p->x[k] - start[k]));
                }
            const char *name = how == RK4 ? "RK4" : "Verlet";
            printf("work, %s%s: %.15g J booked, (F + m g) . dx = %.15g J\n", name,
                   with_gravity ? " with gravity" : "", r.work, expect);
            CHECK(r.status == 0 && fabs(r.work - expect) <= 1e-12 * scale,
                  "%s%s: work %.17g J, (F + m g) . dx %.17g J", name,
                  with_gravity ? " with gravity" : "", r.work, expect);
            test_lattice_free(p);
        }
}

/* A force F1 t on a mass m at rest, the other points at rest and force-free, RK4:
 * the motion v = F1 t^2 / (2m), x - x0 = F1 t^3 / (6m) is exact (RK4 integrates a
 * force polynomial in t of degree <= 3 without error), so the work booked is the
 * trapezoidal rule of F dx on it, which sums to
 *     |F1|^2 / (6m) sum_n (t_n + t_n+1) / 2 (t_n+1^3 - t_n^3)
 *         = |F1|^2 T^4 / (8m) (1 - 1 / (3 n^2))
 * for n steps to T: the exact work of F . v less the rule's error (per step
 * -(t_n h^3 / 2 + h^4 / 4) |F1|^2 / (6m)). Taking the force at both ends of each step
 * (external_prev) matters: the end's alone books 1 / n more. To round-off, 1e-12. */
static void check_ramp_work(void)
{
    const int n = 50;
    springs s;
    solid_particles *p = spring_system(&s);
    memset(s.k, 0, sizeof s.k);
    memset(s.f_const, 0, sizeof s.f_const);
    memcpy(p->x, p->x0, (size_t)p->n * FSI_DIM * sizeof *p->x);
    memset(p->v, 0, (size_t)p->n * FSI_DIM * sizeof *p->v);
    double f1 = 0.0;
    for (int d = 0; d < FSI_DIM; d++) {
        s.ramp[d] = 0.3 - 0.5 * d;
        f1 += s.ramp[d] * s.ramp[d];
    }
    solid_integrator in = {.max_step = 1.0};
    const run_result r = integrate(p, &s, RK4, n, &in);
    const double m = mass(p, 0), t = END_TIME;
    const double expect = f1 * pow(t, 4) / (8.0 * m) * (1.0 - 1.0 / (3.0 * n * n));
    double motion = 0.0;
    for (int d = 0; d < FSI_DIM; d++) {
        motion = fmax(motion, fabs(p->v[d] / (s.ramp[d] * t * t / (2.0 * m)) - 1.0));
        motion = fmax(motion, fabs((p->x[d] - p->x0[d]) / (s.ramp[d] * pow(t, 3) / (6.0 * m)) -
                                   1.0));
    }
    printf("work of a force F1 t, RK4, %d steps: %.15g J booked, %.15g J the trapezoidal "
           "rule's on the exact motion (which is off by %.3g)\n", n, r.work, expect, motion);
    CHECK(r.status == 0 && motion < 1e-12, "RK4 with a force F1 t: the motion is off the "
          "exact cubic by %.3g", motion);
    CHECK(fabs(r.work / expect - 1.0) < 1e-12, "work of F1 t: %.17g J booked, %.17g J expected",
          r.work, expect);
    test_lattice_free(p);
}

static void check_faults(void)
{
    for (int how = VERLET; how <= RK4; how++) {
        const char *name = how == RK4 ? "RK4" : "Verlet";
        springs s;
        solid_particles *p = spring_system(&s);
        /* Steps of 0.5 and 1 s, far beyond the springs' stable step: no displacement
         * limit, so that only the NaN stops the step. */
        solid_integrator in = {.max_step = 1e6};
        /* Two good steps, then a NaN force on point 2 (the first point of the system
         * to fail: 0 and 1 stay finite). */
        run_result r = integrate(p, &s, (scheme)how, 2, &in);
        s.poison = 2;
        const run_result bad = integrate(p, &s, (scheme)how, 1, &in);
        printf("%s, NaN force on point 2: status %d, fault at %d: %s\n", name, bad.status,
               bad.fault.particle, bad.fault.what);
        CHECK(r.status == 0 && bad.status == -1 && bad.fault.particle == 2 &&
                  strstr(bad.fault.what, "not finite"),
              "%s: NaN force gives status %d, particle %d, '%s'", name, bad.status,
              bad.fault.particle, bad.fault.what);
        test_lattice_free(p);

        /* A step longer than max_step: point 0 moves first. */
        p = spring_system(&s);
        in.max_step = 1e-9;
        r = integrate(p, &s, (scheme)how, 1, &in);
        printf("%s, max_step 1e-9 m: status %d, fault at %d: %s\n", name, r.status,
               r.fault.particle, r.fault.what);
        CHECK(r.status == -1 && r.fault.particle == 0 && strstr(r.fault.what, "moved"),
              "%s: a step beyond max_step gives status %d, particle %d, '%s'", name, r.status,
              r.fault.particle, r.fault.what);
        test_lattice_free(p);
    }
    /* A callback that fails: -2, its own message standing (the fault is not set). */
    springs s;
    solid_particles *p = spring_system(&s);
    solid_integrator in = {.max_step = 1.0};
    s.fail = 1;
    const run_result r = integrate(p, &s, RK4, 1, &in);
    printf("RK4, failing force callback: status %d\n", r.status);
    CHECK(r.status == -2, "RK4 with a failing force callback returns %d, not -2", r.status);
    test_lattice_free(p);
}

int main(void)
{
    check_orders();
    check_partner_moves();
    check_work();
    check_ramp_work();
    check_faults();
    return unit_check_report("test_solid_integrators");
}
