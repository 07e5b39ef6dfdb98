#include "fluid_diagnostics.h"

#include <math.h>
#include <stdio.h>

#include "small_tensor.h"
#include "units.h"

double fluid_kinetic_energy(const fluid_particles *p)
{
    double e = 0.0;
    for (int i = 0; i < p->n; i++)
        if (p->flags[i] & FLUID_PARTICLE_FLUID)
            e += 0.5 * p->mass[i] * fsi_vec_dot(&p->v[i * FSI_DIM], &p->v[i * FSI_DIM]);
    return e;
}

double fluid_potential_energy(const fluid_particles *p, const double *gravity)
{
    double e = 0.0;
    for (int i = 0; i < p->n; i++)
        if (p->flags[i] & FLUID_PARTICLE_FLUID)
            e -= p->mass[i] * fsi_vec_dot(gravity, &p->x[i * FSI_DIM]);
    return e;
}

double fluid_compression_energy(const fluid_particles *p, const fluid_scheme *s)
{
    if (!fluid_scheme_compressible(s))
        return 0.0;
    double e = 0.0;
    for (int i = 0; i < p->n; i++)
        if (p->flags[i] & FLUID_PARTICLE_FLUID)
            e += p->mass[i] * fluid_scheme_compression_energy(s, p->density[i]);
    return e;
}

double fluid_max_speed(const fluid_particles *p)
{
    double v2 = 0.0;
    for (int i = 0; i < p->n; i++)
        if (p->flags[i] & FLUID_PARTICLE_FLUID)
            v2 = fmax(v2, fsi_vec_dot(&p->v[i * FSI_DIM], &p->v[i * FSI_DIM]));
    return sqrt(v2);
}

/* The columns after "time" (docs/output.md lists them with their meaning). */
static char *const columns[] = {
#define J "[" FSI_UNIT_ENERGY "]"
    "window", "dt [s]", "steps", "step [s]", "kinetic_energy " J, "potential_energy " J,
    "compression_energy " J, "wall_work " J, "interface_work " J, "boundary_work " J,
    "particles_inside", "max_speed [m/s]",
#undef J
};
enum { N_COLUMNS = sizeof columns / sizeof columns[0] };

int fluid_diagnostics_open(fluid_diagnostics *d, const char *dir, const char *name,
                           off_t resume, char *msg, size_t msg_size)
{
    return fsi_diagnostics_csv_open(&d->file, dir, name, N_COLUMNS, columns, resume, msg,
                                    msg_size);
}

int fluid_diagnostics_write(fluid_diagnostics *d, double t, const fluid_particles *p,
                            const fluid_scheme *s, const double *gravity,
                            const fluid_window_summary *w, char *msg, size_t msg_size)
{
    /* The potential of the unwrapped motion: gravity along a periodic axis keeps doing
     * work that the wrapped positions would hide. */
    const double values[N_COLUMNS] = {
        w->window, w->dt, (double)w->steps, w->step, fluid_kinetic_energy(p),
        fluid_potential_energy(p, gravity) + w->potential_wrapped,
        fluid_compression_energy(p, s), w->wall_work, w->interface_work, w->boundary_work,
        w->inside, w->max_speed,
    };
    return fsi_diagnostics_csv_row(&d->file, t, values, msg, msg_size);
}

off_t fluid_diagnostics_bytes(const fluid_diagnostics *d)
{
    return fsi_diagnostics_csv_bytes(&d->file);
}

void fluid_diagnostics_close(fluid_diagnostics *d)
{
    fsi_diagnostics_csv_close(&d->file);
}
