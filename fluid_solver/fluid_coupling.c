/* The fluid's side of the coupling (fluid_coupling.h). */
#include "fluid_coupling.h"

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

/* a (cap items of size bytes) resized to new_cap items, the new ones zero; NULL when
 * memory runs out (a is then unchanged). */
static void *resize(void *a, int cap, int new_cap, size_t size)
{
    unsigned char *b = realloc(a, (size_t)new_cap * size);
    if (b && new_cap > cap)
        memset(b + (size_t)cap * size, 0, (size_t)(new_cap - cap) * size);
    return b;
}

/* The capacity to grow to for n items (n itself when cap already holds it). */
static int next_capacity(int cap, int n)
{
    return n <= cap ? cap : n + n / 4 + 16;
}

/* The loads of the last window for the particles the solid just sent. */
static int publish(fluid_coupling *c, fsi_participant *part, const fsi_interface *solid,
                   char *msg, size_t msg_size)
{
    const int m = solid->n;
    const int cap = c->out_capacity, new_cap = next_capacity(cap, m);
    if (new_cap > cap || !c->out_id) {
        int32_t *id = resize(c->out_id, cap, new_cap, sizeof *id);
        if (id)
            c->out_id = id;
        double *force = resize(c->out_force, cap, new_cap, FSI_DIM * sizeof *force);
        if (force)
            c->out_force = force;
        double *pressure = resize(c->out_pressure, cap, new_cap, sizeof *pressure);
        if (pressure)
            c->out_pressure = pressure;
        if (!id || !force || !pressure) {
            snprintf(msg, msg_size, "out of memory for the loads of %d particles", m);
            return -1;
        }
        c->out_capacity = new_cap;
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
    const int new_cap = next_capacity(c->impulse_capacity, solid.n);
    if (new_cap > c->impulse_capacity || !c->impulse) {
        double *impulse = resize(c->impulse, c->impulse_capacity, new_cap, FSI_DIM * sizeof *impulse);
        if (!impulse) {
            snprintf(msg, msg_size, "out of memory for the loads of %d particles", solid.n);
            return -1;
        }
        c->impulse = impulse;
        c->impulse_capacity = new_cap;
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
    const int new_cap = next_capacity(c->force_capacity, p->n);
    if (new_cap > c->force_capacity || !c->force) {
        double *force = resize(c->force, c->force_capacity, new_cap, FSI_DIM * sizeof *force);
        if (!force)
            return -1;
        c->force = force;
        c->force_capacity = new_cap;
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
    const int cap = c->id_capacity, new_cap = next_capacity(cap, max_id + 1);
    if (new_cap > cap || !c->known) {
        double *force = resize(c->force_by_id, cap, new_cap, FSI_DIM * sizeof *force);
        if (force)
            c->force_by_id = force;
        double *pressure = resize(c->pressure_by_id, cap, new_cap, sizeof *pressure);
        if (pressure)
            c->pressure_by_id = pressure;
        unsigned char *known = resize(c->known, cap, new_cap, 1);
        if (known)
            c->known = known;
        if (!force || !pressure || !known)
            return -1;
        c->id_capacity = new_cap;
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
