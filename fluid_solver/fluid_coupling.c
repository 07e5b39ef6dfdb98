/* The fluid's side of the coupling (fluid_coupling.h). */
#include "fluid_coupling.h"

#include "grow.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void fluid_coupling_init(fluid_coupling *c, int n_fixed)
{
    memset(c, 0, sizeof *c);
    fluid_boundary_init(&c->boundary, n_fixed);
}

void fluid_coupling_free(fluid_coupling *c)
{
    const int n_fixed = c->boundary.n_fixed;
    fluid_boundary_free(&c->boundary);
    free(c->impulse);
    free(c->force);
    free(c->force_by_id);
    free(c->pressure_by_id);
    free(c->known);
    free(c->out_id);
    free(c->out_force);
    free(c->out_pressure);
    fluid_coupling_init(c, n_fixed);
}

/* The loads of the last window for the particles the solid just sent. */
static int publish(fluid_coupling *c, fsi_participant *part, const fsi_interface *solid,
                   char *msg, size_t msg_size)
{
    const int m = solid->n;
    if (m > c->out_capacity || !c->out_id) {
        const size_t cap = fsi_grown_capacity((size_t)m);
        int failed = 0;
        c->out_id = fsi_grow(c->out_id, cap * sizeof *c->out_id, &failed);
        c->out_force = fsi_grow(c->out_force, cap * FSI_DIM * sizeof *c->out_force, &failed);
        c->out_pressure = fsi_grow(c->out_pressure, cap * sizeof *c->out_pressure, &failed);
        if (failed) {
            snprintf(msg, msg_size, "out of memory for the loads of %d particles", m);
            return -1;
        }
        c->out_capacity = (int)cap;
    }
    for (int k = 0; k < m; k++) {
        const int32_t id = solid->id[k];
        const int seen = id >= 0 && id < c->id_capacity && c->known[id];
        c->out_id[k] = id;
        c->out_pressure[k] = seen ? c->pressure_by_id[id] : 0.0;
        for (int d = 0; d < FSI_DIM; d++)
            c->out_force[k * FSI_DIM + d] = seen ? c->force_by_id[id * FSI_DIM + d] : 0.0;
    }
    fsi_interface loads = {m, c->out_id, NULL, NULL, NULL, NULL, c->out_pressure, c->out_force};
    if (fsi_write_interface(part, &loads) != 0) {
        snprintf(msg, msg_size, "cannot publish the fluid loads (%d particles)", m);
        return -1;
    }
    return 0;
}

int fluid_coupling_exchange(fluid_coupling *c, fsi_participant *part, fluid_particles *p,
                            double rho0, double t0, char *msg, size_t msg_size)
{
    fsi_interface solid;
    fsi_read_interface(part, &solid);
    if (solid.n > 0 && !solid.id) {
        snprintf(msg, msg_size, "the solid sent %d interface particles without ids", solid.n);
        return -1;
    }
    if (publish(c, part, &solid, msg, msg_size) != 0 ||
        fluid_boundary_set(&c->boundary, p, &solid, rho0, msg, msg_size) != 0)
        return -1;
    c->t_window = t0;
    if (solid.n > c->impulse_capacity || !c->impulse) {
        const size_t cap = fsi_grown_capacity((size_t)solid.n);
        int failed = 0;
        c->impulse = fsi_grow(c->impulse, cap * FSI_DIM * sizeof *c->impulse, &failed);
        if (failed) {
            snprintf(msg, msg_size, "out of memory for the loads of %d particles", solid.n);
            return -1;
        }
        c->impulse_capacity = (int)cap;
    }
    memset(c->impulse, 0, (size_t)solid.n * FSI_DIM * sizeof *c->impulse);
    c->n_windows += solid.n > 0;
    return 0;
}

void fluid_coupling_move(const fluid_coupling *c, fluid_particles *p, double t)
{
    fluid_boundary_move(&c->boundary, p, t - c->t_window);
}

int fluid_coupling_accumulate(fluid_coupling *c, const fluid_scheme *scheme,
                              const fluid_particles *p, double h)
{
    const fluid_boundary *b = &c->boundary;
    if (b->n == 0)
        return 0;
    if (p->n > c->force_capacity || !c->force) {
        const size_t cap = fsi_grown_capacity((size_t)p->n);
        int failed = 0;
        c->force = fsi_grow(c->force, cap * FSI_DIM * sizeof *c->force, &failed);
        if (failed)
            return -1;
        c->force_capacity = (int)cap;
    }
    fluid_scheme_boundary_loads(scheme, p, c->force);
    for (int k = 0; k < b->n * FSI_DIM; k++)
        c->impulse[k] += h * c->force[b->n_fixed * FSI_DIM + k];
    return 0;
}

int fluid_coupling_end_window(fluid_coupling *c, const fluid_particles *p, double dt)
{
    const fluid_boundary *b = &c->boundary;
    int max_id = -1;
    for (int k = 0; k < b->n; k++)
        if (p->id[b->n_fixed + k] > max_id)
            max_id = p->id[b->n_fixed + k];
    if (max_id + 1 > c->id_capacity || !c->known) {
        const size_t cap = fsi_grown_capacity((size_t)(max_id + 1));
        int failed = 0;
        c->force_by_id = fsi_grow(c->force_by_id, cap * FSI_DIM * sizeof *c->force_by_id, &failed);
        c->pressure_by_id = fsi_grow(c->pressure_by_id, cap * sizeof *c->pressure_by_id, &failed);
        c->known = fsi_grow(c->known, cap, &failed);
        if (failed)
            return -1;
        c->id_capacity = (int)cap;
    }
    memset(c->known, 0, (size_t)c->id_capacity);
    for (int k = 0; k < b->n; k++) {
        const int i = b->n_fixed + k, id = p->id[i];
        if (id < 0)
            continue;
        c->known[id] = 1;
        c->pressure_by_id[id] = p->pressure[i];
        for (int d = 0; d < FSI_DIM; d++)
            c->force_by_id[id * FSI_DIM + d] = dt > 0.0 ? c->impulse[k * FSI_DIM + d] / dt : 0.0;
    }
    return 0;
}
