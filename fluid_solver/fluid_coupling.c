/* The fluid's side of the coupling (fluid_coupling.h). */
#include "fluid_coupling.h"

#include "fluid_state.h"
#include "grow.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void fluid_coupling_init(fluid_coupling *c, int n_fixed, double impedance)
{
    memset(c, 0, sizeof *c);
    fluid_boundary_init(&c->boundary, n_fixed);
    fsi_grid_init(&c->solid_grid);
    c->impedance = impedance;
    c->density_min = INFINITY;
    c->density_max = -INFINITY;
}

void fluid_coupling_free(fluid_coupling *c)
{
    const int n_fixed = c->boundary.n_fixed;
    const double impedance = c->impedance;
    fluid_boundary_free(&c->boundary);
    fsi_grid_free(&c->solid_grid);
    free(c->impulse);
    free(c->force);
    free(c->out_id);
    free(c->out_force);
    free(c->out_pressure);
    fluid_coupling_init(c, n_fixed, impedance);
}

int fluid_coupling_receive(fluid_coupling *c, fsi_participant *part, fluid_particles *p,
                           double rho0, double t0, char *msg, size_t msg_size)
{
    fsi_interface solid;
    fsi_read_interface(part, &solid);
    return fluid_coupling_start_window(c, p, &solid, rho0, t0, msg, msg_size);
}

int fluid_coupling_start_window(fluid_coupling *c, fluid_particles *p,
                                const fsi_interface *solid, double rho0, double t0,
                                char *msg, size_t msg_size)
{
    if (solid->n > 0 && !solid->id) {
        snprintf(msg, msg_size, "the solid sent %d interface particles without ids", solid->n);
        return -1;
    }
    if (fluid_boundary_set(&c->boundary, p, solid, rho0, msg, msg_size) != 0)
        return -1;
    for (int k = 0; k < solid->n; k++) {
        c->density_min = fmin(c->density_min, solid->density[k]);
        c->density_max = fmax(c->density_max, solid->density[k]);
    }
    c->t_window = t0;
    if (solid->n > c->impulse_capacity || !c->impulse) {
        const size_t cap = fsi_grown_capacity((size_t)solid->n);
        int failed = 0;
        c->impulse = fsi_grow(c->impulse, cap * FSI_DIM * sizeof *c->impulse, &failed);
        if (failed) {
            snprintf(msg, msg_size, "out of memory for the loads of %d particles", solid->n);
            return -1;
        }
        c->impulse_capacity = (int)cap;
    }
    memset(c->impulse, 0, (size_t)solid->n * FSI_DIM * sizeof *c->impulse);
    c->n_windows += solid->n > 0;
    return 0;
}

void fluid_coupling_move(const fluid_coupling *c, fluid_particles *p, double t)
{
    fluid_boundary_move(&c->boundary, p, t - c->t_window);
}

/* The force on every particle from the last evaluation of the rates into c->force
 * (only the boundary tail is used). 0, or -1 when memory runs out. */
static int boundary_forces(fluid_coupling *c, const fluid_scheme *scheme,
                           const fluid_particles *p)
{
    if (p->n > c->force_capacity || !c->force) {
        const size_t cap = fsi_grown_capacity((size_t)p->n);
        int failed = 0;
        c->force = fsi_grow(c->force, cap * FSI_DIM * sizeof *c->force, &failed);
        if (failed)
            return -1;
        c->force_capacity = (int)cap;
    }
    fluid_scheme_boundary_loads(scheme, p, c->force);
    return 0;
}

int fluid_coupling_accumulate(fluid_coupling *c, const fluid_scheme *scheme,
                              const fluid_particles *p, double h)
{
    if (c->boundary.n == 0)
        return 0;
    if (boundary_forces(c, scheme, p) != 0)
        return -1;
    fluid_coupling_add_loads(c, p, c->force, h);
    return 0;
}

void fluid_coupling_add_loads(fluid_coupling *c, const fluid_particles *p,
                              const double *force, double h)
{
    const fluid_boundary *b = &c->boundary;
    const double *f = force + (size_t)b->n_fixed * FSI_DIM;
    const double *v = p->v + (size_t)b->n_fixed * FSI_DIM;
    double power = 0.0, power_at_sent = 0.0, total[FSI_DIM] = {0};
    for (int k = 0; k < b->n * FSI_DIM; k++) {
        c->impulse[k] += h * f[k];
        power -= f[k] * v[k];
        power_at_sent += f[k] * b->v_start[k];
        total[k % FSI_DIM] += f[k];
    }
    c->work_on_fluid += h * power;
    c->work_at_sent += h * power_at_sent;
    for (int d = 0; d < FSI_DIM; d++)
        c->impulse_sent[d] += h * total[d];
}

int fluid_coupling_publish(fluid_coupling *c, fsi_participant *part,
                           const fluid_scheme *scheme, const fluid_particles *p, double dt,
                           char *msg, size_t msg_size)
{
    const int m = c->boundary.n;
    if ((m > 0 && !(dt > 0.0) && boundary_forces(c, scheme, p) != 0) ||
        fluid_coupling_window_loads(c, p, dt) != 0) {
        snprintf(msg, msg_size, "out of memory for the loads of %d particles", m);
        return -1;
    }
    fsi_interface loads = {.n = m, .id = c->out_id, .pressure = c->out_pressure,
                           .force = c->out_force, .impedance = c->impedance};
    if (fsi_write_interface(part, &loads) != 0) {
        snprintf(msg, msg_size, "cannot publish the fluid loads (%d particles)", m);
        return -1;
    }
    return 0;
}

int fluid_coupling_window_loads(fluid_coupling *c, const fluid_particles *p, double dt)
{
    const fluid_boundary *b = &c->boundary;
    const int m = b->n;
    if (m > c->out_capacity || !c->out_id) {
        const size_t cap = fsi_grown_capacity((size_t)m);
        int failed = 0;
        c->out_id = fsi_grow(c->out_id, cap * sizeof *c->out_id, &failed);
        c->out_force = fsi_grow(c->out_force, cap * FSI_DIM * sizeof *c->out_force, &failed);
        c->out_pressure = fsi_grow(c->out_pressure, cap * sizeof *c->out_pressure, &failed);
        if (failed)
            return -1;
        c->out_capacity = (int)cap;
    }
    const int instant = !(dt > 0.0);
    for (int k = 0; k < m; k++) {
        const int i = b->n_fixed + k;
        c->out_id[k] = p->id[i];
        c->out_pressure[k] = p->pressure[i];
        for (int d = 0; d < FSI_DIM; d++)
            c->out_force[k * FSI_DIM + d] = instant ? c->force[i * FSI_DIM + d]
                                                    : c->impulse[k * FSI_DIM + d] / dt;
    }
    return 0;
}

/* Whether x is closer to a solid particle than half that particle's spacing; r is the
 * largest such half spacing. */
static int closer_than_half_spacing(const fsi_neighbour_grid *grid, const double *x, double r,
                                    const double *volume)
{
    enum { MAX_NEAR = 64 };
    int near[MAX_NEAR];
    double r2[MAX_NEAR];
    const int n = fsi_grid_neighbours(grid, x, r, near, r2, MAX_NEAR);
    for (int k = 0; k < n && k < MAX_NEAR; k++) {
        const double half = 0.5 * fluid_particle_side(volume[near[k]]);
        if (r2[k] < half * half)
            return 1;
    }
    return 0;
}

int fluid_coupling_count_inside(fluid_coupling *c, const fluid_particles *p, int *first)
{
    const fluid_boundary *b = &c->boundary;
    *first = -1;
    if (b->n == 0)
        return 0;
    const double *xb = p->x + (size_t)b->n_fixed * FSI_DIM;
    const double *vb = p->volume + b->n_fixed;
    double r = 0.0; /* the largest half spacing of a solid particle */
    for (int k = 0; k < b->n; k++)
        r = fmax(r, 0.5 * fluid_particle_side(vb[k]));
    if (fsi_grid_build(&c->solid_grid, xb, b->n, r) != 0)
        return -1;
    /* Only fluid particles in the solid's bounding box (grown by r) can be inside. */
    double lo[FSI_DIM], hi[FSI_DIM];
    for (int d = 0; d < FSI_DIM; d++) {
        lo[d] = hi[d] = xb[d];
        for (int k = 1; k < b->n; k++) {
            lo[d] = fmin(lo[d], xb[k * FSI_DIM + d]);
            hi[d] = fmax(hi[d], xb[k * FSI_DIM + d]);
        }
        lo[d] -= r;
        hi[d] += r;
    }
    int count = 0;
    for (int i = 0; i < b->n_fixed; i++) {
        if (!(p->flags[i] & FLUID_PARTICLE_FLUID))
            continue;
        const double *x = &p->x[i * FSI_DIM];
        int in_box = 1;
        for (int d = 0; d < FSI_DIM; d++)
            in_box &= x[d] >= lo[d] && x[d] <= hi[d];
        if (in_box && closer_than_half_spacing(&c->solid_grid, x, r, vb)) {
            if (count == 0)
                *first = i;
            count++;
        }
    }
    return count;
}

/* The totals (no padding: the state is compared byte for byte). */
typedef struct {
    int64_t n_windows;
    double work_on_fluid, work_at_sent, impulse_sent[FSI_DIM], density_min, density_max;
} coupling_totals;

int fluid_coupling_save_state(const fluid_coupling *c, fsi_state *st, const char *prefix)
{
    coupling_totals t = {c->n_windows, c->work_on_fluid, c->work_at_sent, {0},
                         c->density_min, c->density_max};
    memcpy(t.impulse_sent, c->impulse_sent, sizeof t.impulse_sent);
    return fluid_state_put(st, prefix, "totals", &t, sizeof t);
}

int fluid_coupling_restore_state(fluid_coupling *c, const fsi_state *st, const char *prefix)
{
    coupling_totals t;
    if (fluid_state_get(st, prefix, "totals", &t, sizeof t) != 0)
        return -1;
    c->n_windows = (int)t.n_windows;
    c->work_on_fluid = t.work_on_fluid;
    c->work_at_sent = t.work_at_sent;
    memcpy(c->impulse_sent, t.impulse_sent, sizeof t.impulse_sent);
    c->density_min = t.density_min;
    c->density_max = t.density_max;
    return 0;
}
