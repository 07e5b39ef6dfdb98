/* Time integration of the solid: velocity Verlet (000 Eq. 55) with mass-proportional
 * damping, gravity, clamps, and the cheap per-sub-step health checks; plus the
 * energy bookkeeping of the energy check.
 *
 * One sub-step of length h from t_n to t_{n+1} (000 Eq. 55):
 *     v_{n+1/2} = v_n + h/2 a_n                      solid_verlet_drift
 *     x_{n+1}   = x_n + h v_{n+1/2}
 *     F_{n+1}   = f_int(x_{n+1}) + f_ext(t_{n+1})    (the model and the main loop)
 *     v_{n+1}   = v_{n+1/2} + h/2 a_{n+1}            solid_verlet_kick
 *     a_{n+1}   = F_{n+1} / m + g - c v_{n+1}
 * The damping term -c v makes the last two lines implicit in v_{n+1}; solved exactly,
 *     v_{n+1} = (v_{n+1/2} + h/2 (F_{n+1} / m + g)) / (1 + c h / 2),
 * which is stable for any c >= 0 (an explicit -c v_{n+1/2} would need c h < 2) and
 * reduces to Eq. 55 for c = 0. Clamped points keep x = x0, v = a = 0, except mirrored
 * ones (SOLID_MIRRORED), which follow their partner m: x - x0 = -(x_m - x0_m),
 * v = -v_m, a = -a_m. Such a point is a function of its partner's position, so the
 * internal force on it belongs to the partner with the opposite sign
 * (solid_mirror_forces): the dynamics stay those of an energy. */
#ifndef FSI_SOLID_INTEGRATE_H
#define FSI_SOLID_INTEGRATE_H

#include "dim.h"
#include "solid_particles.h"

typedef struct {
    double damping;             /* c [1/s] */
    /* Per particle, added to c (NULL: none): the fluid's impedance on the interface
     * particles (solid_interface.h) [1/s]. */
    const double *particle_damping;
    double gravity[FSI_DIM];    /* g [m/s^2] */
    /* Largest displacement of a point in one sub-step before it counts as unstable
     * [m]; the main loop uses one spacing: a stable explicit step moves points by
     * v h = (v / c_wave) * safety * dx, a small fraction of dx for any real motion. */
    double max_step;
} solid_integrator;

/* Forces on every particle, n * FSI_DIM each [N]. 'external' is everything but the
 * internal force and gravity: prescribed loads plus the fluid's load. */
typedef struct {
    const double *internal;
    const double *external;
    const double *external_prev;    /* 'external' at the start of the sub-step (work) */
} solid_forces;

/* What went wrong at which particle when a sub-step failed. */
typedef struct {
    int particle;               /* index, -1 when nothing failed */
    char what[96];              /* e.g. "velocity is not finite" */
} solid_fault;

/* a = (internal + external) / m + g - c v, clamped points 0 (external_prev unused):
 * the acceleration at the start of a window, after new fluid loads arrived. */
void solid_acceleration(solid_particles *p, const solid_forces *f, const solid_integrator *in);

/* First half of a sub-step: x_prev = x, v += h/2 a, x += h v; clamped: x = x0, v = 0. */
void solid_verlet_drift(solid_particles *p, double h, double *x_prev);

/* Second half, with the forces at the new positions. Checks every point: finite
 * x, v, a and a displacement since x_prev of at most max_step. Adds the work the
 * external forces and gravity did over the sub-step (trapezoidal rule on
 * F . (x - x_prev), with the interface impedance's -m c_i v at the mean velocity
 * (x - x_prev) / h) to *work. Returns 0, or -1 with *fault set to the first failing
 * particle. */
int solid_verlet_kick(solid_particles *p, const solid_forces *f, double h,
                      const solid_integrator *in, const double *x_prev, double *work,
                      solid_fault *fault);

/* The checks and the work bookkeeping of solid_verlet_kick, for a step whose x, v
 * and a are final (every integrator's last act): finite x, v, a and a displacement
 * since x_prev of at most max_step for every unclamped point; the external forces'
 * work over the step added to *work. Returns 0, or -1 with *fault set. */
int solid_step_end(const solid_particles *p, const solid_forces *f, double h,
                   const solid_integrator *in, const double *x_prev, double *work,
                   solid_fault *fault);

/* x, v, a of every mirrored point from its partner's. */
void solid_follow_partners(solid_particles *p);

/* Moves the internal force of every mirrored point onto its partner (f_m -= f_g,
 * f_g = 0: x_g depends on x_m with the Jacobian -I). Nothing without mirrored points. */
void solid_mirror_forces(const solid_particles *p, double *internal);

/* Kinetic energy sum 1/2 m v^2 over material points (not mirrored ones) [J, per unit
 * thickness in 2D]. */
double solid_kinetic_energy(const solid_particles *p);

/* Gravity's potential -sum m g . x over material points, zero at the origin [J, per
 * unit thickness in 2D]. */
double solid_potential_energy(const solid_particles *p, const double *gravity);

/* Total mass of the material points [kg, per unit thickness in 2D]. */
double solid_total_mass(const solid_particles *p);

#endif
