/* Interface gather and load take (solid_interface.h). */
#include "solid_interface.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lattice_ball.h"
#include "neighbour_grid.h"

int solid_interface_init(solid_interface_buffers *b, int n_particles)
{
    memset(b, 0, sizeof *b);
    size_t n = n_particles > 0 ? (size_t)n_particles : 1, v = n * FSI_DIM;
    b->surface = calloc(n, 1);
    b->band = calloc(n, 1);
    b->received = calloc(n, 1);
    b->state.id = malloc(n * sizeof *b->state.id);
    b->state.position = malloc(v * sizeof(double));
    b->state.velocity = malloc(v * sizeof(double));
    b->state.acceleration = malloc(v * sizeof(double));
    b->state.volume = malloc(n * sizeof(double));
    b->state.density = malloc(n * sizeof(double));
    b->x_window = malloc(v * sizeof(double));
    b->v_mean = calloc(v, sizeof(double));   /* read (times 0) before a first gather */
    b->u_fluid = calloc(v, sizeof(double));
    b->end_position = malloc(v * sizeof(double));
    if (!b->surface || !b->band || !b->received || !b->state.id || !b->state.position ||
        !b->state.velocity || !b->state.acceleration || !b->state.volume ||
        !b->state.density || !b->x_window || !b->v_mean || !b->u_fluid || !b->end_position) {
        solid_interface_free(b);
        return -1;
    }
    b->capacity = n_particles;
    b->density_min = INFINITY;
    b->density_max = -INFINITY;
    return 0;
}

void solid_interface_free(solid_interface_buffers *b)
{
    free(b->surface);
    free(b->band);
    free(b->received);
    free(b->state.id);
    free(b->state.position);
    free(b->state.velocity);
    free(b->state.acceleration);
    free(b->state.volume);
    free(b->state.density);
    free(b->x_window);
    free(b->v_mean);
    free(b->u_fluid);
    free(b->end_position);
    memset(b, 0, sizeof *b);
}

double solid_interface_fluid_reach(const fsi_case *c, double *fluid_spacing)
{
    const double dx_f = fsi_case_get_real(c, "fluid", "spacing", 0.0);
    if (fluid_spacing)
        *fluid_spacing = dx_f > 0.0 ? dx_f : 0.0;
    const double support = fsi_case_get_real(c, "fluid", FSI_CASE_SUPPORT_KEY, 0.0);
    if (!(dx_f > 0.0) || !(support > 0.0))
        return 0.0;
    return support - 0.5 * dx_f;
}

double solid_interface_depth(const fsi_case *c)
{
    const double given = fsi_case_get_real(c, "solid", "interface_depth", 0.0);
    return given > 0.0 ? given : solid_interface_fluid_reach(c, NULL);
}

/* The neighbours within r an interior lattice point has. */
static long lattice_count(double r, double dx)
{
    long count = 0;
    fsi_lattice_ball ball;
    double len;
    fsi_lattice_ball_begin(&ball, r, dx);
    while (fsi_lattice_ball_next(&ball, &len))
        count++;
    return count;
}

int solid_interface_band(solid_interface_buffers *b, const solid_particles *p, double depth)
{
    const int n_all = p->n < b->capacity ? p->n : b->capacity;
    memset(b->band, 0, (size_t)b->capacity);
    if (!(depth > 0.0) || n_all == 0)
        return 0;
    /* The tolerance of the model's horizon (nosbpd_bonds.h): lattice distances that
     * equal the radius up to round-off count as inside. */
    const double dx = p->spacing, r = depth + 0.5 * dx + 1e-6 * dx;
    const long full = lattice_count(r, dx);
    fsi_neighbour_grid grid;
    fsi_grid_init(&grid);
    if (fsi_grid_build(&grid, p->x0, n_all, r) != 0)
        return -1;
    int count = 0;
    for (int i = 0; i < n_all; i++) {
        if (p->flags[i] & SOLID_MIRRORED)
            continue;
        /* p's own point is reported too. */
        const long near = (long)fsi_grid_neighbours(&grid, &p->x0[i * FSI_DIM], r, NULL, NULL,
                                                    0) - 1;
        b->band[i] = near < full;
        count += b->band[i];
    }
    fsi_grid_free(&grid);
    return count;
}

int solid_interface_gather(solid_interface_buffers *b, const solid_particles *p,
                           const double *density, double dt_last)
{
    const int n_all = p->n < b->capacity ? p->n : b->capacity;
    const int have_mean = b->have_x_window && dt_last > 0.0;
    const int have_change = have_mean && b->dt_mean > 0.0;
    const double dt_change = have_change ? 0.5 * (dt_last + b->dt_mean) : 1.0;
    int n = 0;
    for (int i = 0; i < n_all; i++) {
        double v_mean[FSI_DIM], a_mean[FSI_DIM];
        for (int d = 0; d < FSI_DIM; d++) {
            const int k = i * FSI_DIM + d;
            v_mean[d] = have_mean ? (p->x[k] - b->x_window[k]) / dt_last : p->v[k];
            a_mean[d] = have_change ? (v_mean[d] - b->v_mean[k]) / dt_change
                        : have_mean ? 0.0
                                    : p->a[k];
            b->x_window[k] = p->x[k];
            b->v_mean[k] = v_mean[d];
        }
        if (!b->surface[i] && !b->band[i])
            continue;
        b->state.id[n] = p->id[i];
        for (int d = 0; d < FSI_DIM; d++) {
            b->state.position[n * FSI_DIM + d] = p->x[i * FSI_DIM + d];
            b->state.velocity[n * FSI_DIM + d] = v_mean[d];
            b->state.acceleration[n * FSI_DIM + d] = a_mean[d];
        }
        b->state.volume[n] = p->volume[i];
        b->state.density[n] = density[i];
        b->density_min = fmin(b->density_min, density[i]);
        b->density_max = fmax(b->density_max, density[i]);
        n++;
    }
    b->have_x_window = 1;
    b->dt_mean = have_mean ? dt_last : 0.0;
    b->state.n = n;
    return n;
}

int solid_interface_take(solid_interface_buffers *b, const fsi_interface *in,
                         const solid_particles *p, double *force, double *pressure, char *msg,
                         size_t msg_size)
{
    memset(force, 0, (size_t)p->n * FSI_DIM * sizeof *force);
    if (pressure)
        memset(pressure, 0, (size_t)p->n * sizeof *pressure);
    memset(b->received, 0, (size_t)b->capacity);
    const int n_all = p->n < b->capacity ? p->n : b->capacity;
    memcpy(b->u_fluid, b->v_mean, (size_t)n_all * FSI_DIM * sizeof *b->u_fluid);
    if (in->n <= 0)
        return 0;
    if (!in->id || !in->force) {
        snprintf(msg, msg_size, "the fluid sent %d loads without ids or forces", in->n);
        return -1;
    }
    for (int j = 0; j < in->n; j++) {
        int32_t id = in->id[j];
        if (id < 0 || id >= p->n || id >= b->capacity) {
            snprintf(msg, msg_size, "the fluid sent a load for particle id %d, which does not "
                     "exist (the solid has %d particles)", (int)id, p->n);
            return -1;
        }
        if (!b->surface[id] && !b->band[id]) {
            snprintf(msg, msg_size, "the fluid sent a load for particle id %d, which was not "
                     "sent to it in this window", (int)id);
            return -1;
        }
        if (b->received[id]) {
            snprintf(msg, msg_size, "the fluid sent two loads for particle id %d", (int)id);
            return -1;
        }
        b->received[id] = 1;
        for (int d = 0; d < FSI_DIM; d++) {
            double f = in->force[j * FSI_DIM + d];
            if (!isfinite(f)) {
                snprintf(msg, msg_size, "the fluid's force on particle id %d is not finite",
                         (int)id);
                return -1;
            }
            force[id * FSI_DIM + d] = f;
        }
        for (int d = 0; in->velocity && d < FSI_DIM; d++) {
            double u = in->velocity[j * FSI_DIM + d];
            if (!isfinite(u)) {
                snprintf(msg, msg_size, "the velocity the fluid moved particle id %d with "
                         "is not finite", (int)id);
                return -1;
            }
            b->u_fluid[id * FSI_DIM + d] = u;
        }
        if (pressure && in->pressure)
            pressure[id] = in->pressure[j];
    }
    return 0;
}

void solid_interface_window_end(solid_interface_buffers *b, const solid_particles *p,
                                fsi_interface *end)
{
    for (int j = 0; j < b->state.n; j++)
        for (int d = 0; d < FSI_DIM; d++)
            b->end_position[j * FSI_DIM + d] = p->x[b->state.id[j] * FSI_DIM + d];
    *end = (fsi_interface){.n = b->state.n, .id = b->state.id, .position = b->end_position};
}

void solid_interface_damping(const solid_interface_buffers *b, const solid_particles *p,
                             const double *force, double impedance, double *damping)
{
    const double area = pow(p->spacing, FSI_DIM - 1) *
                        (b->fluid_spacing > 0.0 ? p->spacing / b->fluid_spacing : 1.0);
    const int n_all = p->n < b->capacity ? p->n : b->capacity;
    for (int i = 0; i < n_all; i++) {
        int loaded = 0;
        for (int d = 0; d < FSI_DIM; d++)
            loaded |= force[i * FSI_DIM + d] != 0.0;
        damping[i] = b->received[i] && loaded && impedance > 0.0
                         ? impedance * area / (p->density[i] * p->volume[i])
                         : 0.0;
    }
}
