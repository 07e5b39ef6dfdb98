/* Moving boundary particles fed from the coupling (fluid_boundary.h). */
#include "fluid_boundary.h"

#include "grow.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void fluid_boundary_init(fluid_boundary *b, int n_fixed)
{
    *b = (fluid_boundary){0};
    b->n_fixed = n_fixed;
    b->acceleration_in_pressure = 1;
}

void fluid_boundary_free(fluid_boundary *b)
{
    free(b->x_start);
    free(b->v_start);
    free(b->acceleration);
    fluid_boundary_init(b, b->n_fixed);
}

static int reserve(fluid_boundary *b, int n)
{
    if (n <= b->capacity)
        return 0;
    const size_t cap = fsi_grown_capacity((size_t)n);
    int failed = 0;
    b->x_start = fsi_grow(b->x_start, cap * FSI_DIM * sizeof *b->x_start, &failed);
    b->v_start = fsi_grow(b->v_start, cap * FSI_DIM * sizeof *b->v_start, &failed);
    b->acceleration = fsi_grow(b->acceleration, cap * FSI_DIM * sizeof *b->acceleration, &failed);
    if (failed)
        return -1;
    b->capacity = (int)cap;
    return 0;
}

/* The index of the first particle of solid whose data cannot be used, or -1. */
static int first_unusable(const fsi_interface *solid)
{
    for (int i = 0; i < solid->n; i++) {
        int ok = isfinite(solid->volume[i]) && solid->volume[i] > 0.0 &&
                 isfinite(solid->density[i]) && solid->density[i] > 0.0;
        for (int d = 0; d < FSI_DIM; d++) {
            const int k = i * FSI_DIM + d;
            ok = ok && isfinite(solid->position[k]) && isfinite(solid->velocity[k]) &&
                 (!solid->acceleration || isfinite(solid->acceleration[k]));
        }
        if (!ok)
            return i;
    }
    return -1;
}

int fluid_boundary_set(fluid_boundary *b, fluid_particles *p, const fsi_interface *solid,
                       double rho0, char *msg, size_t msg_size)
{
    const int m = solid->n;
    if (m < 0 || (m > 0 && (!solid->id || !solid->position || !solid->velocity ||
                            !solid->volume || !solid->density))) {
        snprintf(msg, msg_size, "the solid's interface message lacks positions, velocities, "
                 "volumes or densities (%d particles)", m);
        return -1;
    }
    const int bad = first_unusable(solid);
    if (bad >= 0) {
        snprintf(msg, msg_size, "the solid's interface particle %d has a non-finite position, "
                 "velocity or acceleration, or a volume (%g m^%d) or density (%g kg/m^3) that "
                 "is not positive", solid->id[bad], solid->volume[bad], FSI_DIM,
                 solid->density[bad]);
        return -1;
    }
    if (reserve(b, m) != 0 || fluid_particles_resize(p, b->n_fixed + m) != 0) {
        snprintf(msg, msg_size, "out of memory for %d moving boundary particles", m);
        return -1;
    }
    const size_t bytes = (size_t)m * FSI_DIM * sizeof(double);
    if (m > 0) {
        memcpy(b->x_start, solid->position, bytes);
        memcpy(b->v_start, solid->velocity, bytes);
        if (solid->acceleration)
            memcpy(b->acceleration, solid->acceleration, bytes);
        else
            memset(b->acceleration, 0, bytes);
    }
    b->n = m;
    for (int k = 0; k < m; k++) {
        const int i = b->n_fixed + k;
        p->id[i] = solid->id[k];
        p->flags[i] = FLUID_PARTICLE_MOVING_BOUNDARY;
        p->volume[i] = solid->volume[k];
        p->boundary_density[i] = solid->density[k];
        p->density[i] = rho0;
        p->mass[i] = rho0 * solid->volume[k];
        p->pressure[i] = 0.0;
    }
    fluid_boundary_move(b, p, 0.0);
    return 0;
}

void fluid_boundary_move(const fluid_boundary *b, fluid_particles *p, double tau)
{
    for (int k = 0; k < b->n * FSI_DIM; k++) {
        const double a = b->acceleration[k];
        const int i = b->n_fixed * FSI_DIM + k;
        p->x[i] = b->x_start[k] + tau * (b->v_start[k] + 0.5 * tau * a);
        p->v[i] = b->v_start[k] + tau * a;
        p->boundary_acceleration[i] = b->acceleration_in_pressure ? a : 0.0;
    }
}
