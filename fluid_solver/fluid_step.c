/* The fluid's step limits (fluid_step.h). */
#include "fluid_step.h"

#include <math.h>

#include "fluid_parallel.h"
#include "small_tensor.h"

double fluid_sound_speed(const fsi_case *c, const char *role, double rho0)
{
    double c0 = fsi_case_get_real(c, role, "sound_speed", 0.0);
    if (c0 > 0.0)
        return c0;
    double u_max = fsi_case_get_real(c, role, "max_velocity", 0.0);
    double p_max = fsi_case_get_real(c, role, "max_pressure", 0.0);
    return 10.0 * fmax(sqrt(p_max / rho0), u_max);
}

void fluid_step_limits_read(fluid_step_limits *l, const fsi_case *c, const char *role)
{
    l->density = fsi_case_get_real(c, role, "density", 1000.0);
    l->viscosity = fsi_case_get_real(c, role, "viscosity", 1e-3);
    l->sound_speed = fluid_sound_speed(c, role, l->density);
    l->h = fsi_case_get_real(c, fsi_case_solver_section(c, role), "smoothing_factor", 1.2) *
           fsi_case_get_real(c, role, "spacing", 0.0);
    /* A scheme may set its own acoustic factor in its section (acoustic_step_factor:
     * the schemes' stable steps differ and a case carries several); else [fluid]'s. */
    const char *own = fsi_case_solver_section(c, role);
    const int own_factor = fsi_case_get_real(c, own, "acoustic_step_factor", 0.0) > 0.0;
    l->cfl_acoustic_section = own_factor ? own : role;
    l->cfl_acoustic_key = own_factor ? "acoustic_step_factor" : "cfl_acoustic";
    l->cfl_acoustic = fsi_case_get_real(c, l->cfl_acoustic_section, l->cfl_acoustic_key, 0.25);
    l->cfl_viscous = fsi_case_get_real(c, role, "cfl_viscous", 0.125);
    l->cfl_force = fsi_case_get_real(c, role, "cfl_force", 0.25);
}

double fluid_acoustic_step(const fluid_step_limits *l, double vmax)
{
    return l->cfl_acoustic * l->h / (l->sound_speed + vmax);
}

double fluid_viscous_step(const fluid_step_limits *l)
{
    return l->viscosity > 0.0 ? l->cfl_viscous * l->density * l->h * l->h / l->viscosity
                              : INFINITY;
}

double fluid_stable_step(const fluid_step_limits *l, double vmax, double amax)
{
    double dt = fmin(fluid_acoustic_step(l, vmax), fluid_viscous_step(l));
    if (amax > 0.0)
        dt = fmin(dt, l->cfl_force * sqrt(l->h / amax));
    return dt;
}

double fluid_largest_speed(const fluid_particles *p)
{
    double vmax = 0.0;
    const int n = p->n;
#pragma omp parallel for schedule(static) reduction(max : vmax) \
    if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++)
        if (p->flags[i] & FLUID_PARTICLE_FLUID)
            vmax = fmax(vmax, fsi_vec_norm(&p->v[i * FSI_DIM]));
    return vmax;
}
