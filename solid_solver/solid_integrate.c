/* Velocity Verlet with implicit mass-proportional damping (solid_integrate.h). */
#include "solid_integrate.h"

#include <math.h>
#include <stdio.h>

static double mass_of(const solid_particles *p, int i)
{
    return p->density[i] * p->volume[i];
}

/* x, v, a of every mirrored point from its partner's (solid_integrate.h). */
void solid_follow_partners(solid_particles *p)
{
    if (!p->mirror)
        return;
    for (int i = 0; i < p->n; i++) {
        const int m = p->mirror[i];
        if (m < 0)
            continue;
        for (int d = 0; d < FSI_DIM; d++) {
            const int k = i * FSI_DIM + d, km = m * FSI_DIM + d;
            p->x[k] = p->x0[k] - (p->x[km] - p->x0[km]);
            p->v[k] = -p->v[km];
            p->a[k] = -p->a[km];
        }
    }
}

void solid_mirror_forces(const solid_particles *p, double *internal)
{
    if (!p->mirror)
        return;
    for (int i = 0; i < p->n; i++) {
        const int m = p->mirror[i];
        if (m < 0)
            continue;
        for (int d = 0; d < FSI_DIM; d++) {
            internal[m * FSI_DIM + d] -= internal[i * FSI_DIM + d];
            internal[i * FSI_DIM + d] = 0.0;
        }
    }
}

static double damping_of(const solid_integrator *in, int i)
{
    return in->damping + (in->particle_damping ? in->particle_damping[i] : 0.0);
}

static int is_material(const solid_particles *p, int i)
{
    return !(p->flags[i] & SOLID_MIRRORED);
}

void solid_acceleration(solid_particles *p, const solid_forces *f, const solid_integrator *in)
{
    for (int i = 0; i < p->n; i++) {
        double *a = &p->a[i * FSI_DIM];
        if (p->flags[i] & SOLID_CLAMPED) {
            for (int d = 0; d < FSI_DIM; d++)
                a[d] = 0.0;
            continue;
        }
        double inv_m = 1.0 / mass_of(p, i), c = damping_of(in, i);
        for (int d = 0; d < FSI_DIM; d++) {
            int k = i * FSI_DIM + d;
            a[d] = (f->internal[k] + f->external[k]) * inv_m + in->gravity[d] - c * p->v[k];
        }
    }
    solid_follow_partners(p);
}

void solid_verlet_drift(solid_particles *p, double h, double *x_prev)
{
    for (int i = 0; i < p->n; i++) {
        int clamped = (p->flags[i] & SOLID_CLAMPED) != 0;
        for (int d = 0; d < FSI_DIM; d++) {
            int k = i * FSI_DIM + d;
            x_prev[k] = p->x[k];
            if (clamped) {
                p->x[k] = p->x0[k];
                p->v[k] = 0.0;
                continue;
            }
            p->v[k] += 0.5 * h * p->a[k];
            p->x[k] += h * p->v[k];
        }
    }
    solid_follow_partners(p);
}

int solid_verlet_kick(solid_particles *p, const solid_forces *f, double h,
                      const solid_integrator *in, const double *x_prev, double *work,
                      solid_fault *fault)
{
    for (int i = 0; i < p->n; i++) {
        if (p->flags[i] & SOLID_CLAMPED) {
            for (int d = 0; d < FSI_DIM; d++)
                p->v[i * FSI_DIM + d] = p->a[i * FSI_DIM + d] = 0.0;
            continue;
        }
        double inv_m = 1.0 / mass_of(p, i), c = damping_of(in, i);
        double shrink = 1.0 / (1.0 + 0.5 * c * h);
        for (int d = 0; d < FSI_DIM; d++) {
            int k = i * FSI_DIM + d;
            double force = f->internal[k] + f->external[k];
            double v = (p->v[k] + 0.5 * h * (force * inv_m + in->gravity[d])) * shrink;
            p->v[k] = v;
            p->a[k] = force * inv_m + in->gravity[d] - c * v;
        }
    }
    solid_follow_partners(p);
    return solid_step_end(p, f, h, in, x_prev, work, fault);
}

int solid_step_end(const solid_particles *p, const solid_forces *f, double h,
                   const solid_integrator *in, const double *x_prev, double *work,
                   solid_fault *fault)
{
    double max_step2 = in->max_step * in->max_step;
    double dw = 0.0;
    int bad = -1;
    fault->particle = -1;
    fault->what[0] = '\0';
    for (int i = 0; i < p->n; i++) {
        if (p->flags[i] & SOLID_CLAMPED)
            continue;
        double m = mass_of(p, i), step2 = 0.0;
        double c_interface = in->particle_damping ? in->particle_damping[i] : 0.0;
        int finite = 1;
        for (int d = 0; d < FSI_DIM; d++) {
            int k = i * FSI_DIM + d;
            double dx = p->x[k] - x_prev[k];
            step2 += dx * dx;
            double fe = f->external_prev ? 0.5 * (f->external_prev[k] + f->external[k])
                                         : f->external[k];
            /* The interface impedance's -m c_i v is part of the fluid's force (its
             * m c_i u is in 'external'); the mass-proportional damping is not work. */
            dw += (fe + m * in->gravity[d] - m * c_interface * dx / h) * dx;
            finite &= isfinite(p->x[k]) && isfinite(p->v[k]) && isfinite(p->a[k]);
        }
        /* Remember the first failure only, but finish the loop: the state stays
         * consistent for the message, and the caller stops anyway. */
        if (bad < 0 && (!finite || step2 > max_step2)) {
            bad = i;
            if (!finite)
                snprintf(fault->what, sizeof fault->what,
                         "position, velocity or acceleration is not finite");
            else
                snprintf(fault->what, sizeof fault->what,
                         "moved %.3g m in one sub-step of %.3g s (limit %.3g m)", sqrt(step2),
                         h, in->max_step);
        }
    }
    *work += dw;
    fault->particle = bad;
    return bad < 0 ? 0 : -1;
}

double solid_kinetic_energy(const solid_particles *p)
{
    double e = 0.0;
    for (int i = 0; i < p->n; i++) {
        double v2 = 0.0;
        for (int d = 0; d < FSI_DIM; d++)
            v2 += p->v[i * FSI_DIM + d] * p->v[i * FSI_DIM + d];
        e += is_material(p, i) ? 0.5 * mass_of(p, i) * v2 : 0.0;
    }
    return e;
}

double solid_potential_energy(const solid_particles *p, const double *gravity)
{
    double e = 0.0;
    for (int i = 0; i < p->n; i++) {
        double gx = 0.0;
        for (int d = 0; d < FSI_DIM; d++)
            gx += gravity[d] * p->x[i * FSI_DIM + d];
        e -= is_material(p, i) ? mass_of(p, i) * gx : 0.0;
    }
    return e;
}

double solid_total_mass(const solid_particles *p)
{
    double m = 0.0;
    for (int i = 0; i < p->n; i++)
        m += is_material(p, i) ? mass_of(p, i) : 0.0;
    return m;
}
