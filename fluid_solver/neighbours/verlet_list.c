/* Candidate neighbour lists with a skin: see verlet_list.h. */
#include "verlet_list.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "grow.h"
#include "fluid_parallel.h"
#include "fluid_state.h"

void fluid_verlet_init(fluid_verlet *v)
{
    *v = (fluid_verlet){0};
    fsi_grid_init(&v->grid);
}

void fluid_verlet_free(fluid_verlet *v)
{
    free(v->offset);
    free(v->candidate);
    free(v->idle);
    free(v->x_built);
    fsi_grid_free(&v->grid);
    fluid_verlet_init(v);
}

/* Room for n particles and n_pairs candidates; 0, or -1 when memory runs out. */
static int reserve(fluid_verlet *v, int n, int64_t n_pairs)
{
    int failed = 0;
    if (!v->offset || n > v->point_capacity) {
        const size_t cap = (size_t)n + (size_t)n / 4 + 16;
        v->offset = fsi_grow(v->offset, (cap + 1) * sizeof *v->offset, &failed);
        v->idle = fsi_grow(v->idle, cap * sizeof *v->idle, &failed);
        v->x_built = fsi_grow(v->x_built, cap * FSI_DIM * sizeof *v->x_built, &failed);
        v->point_capacity = failed ? 0 : (int)cap;
    }
    if (!failed && (!v->candidate || n_pairs > v->pair_capacity)) {
        const size_t cap = (size_t)n_pairs + (size_t)n_pairs / 4 + 64;
        v->candidate = fsi_grow(v->candidate, cap * sizeof *v->candidate, &failed);
        v->pair_capacity = failed ? 0 : (int64_t)cap;
    }
    return failed ? -1 : 0;
}

/* Pass 1: the length of i's row (0 for an idle wall, which is marked). */
static int64_t row_length(fluid_verlet *v, const fsi_neighbour_grid *grid,
                          const fluid_particles *p, int i, int prune)
{
    fsi_grid_query q;
    fsi_grid_query_begin(&q, grid, p->x + (int64_t)i * FSI_DIM, v->radius);
    const double radius2 = v->radius * v->radius;
    int64_t count = 0;
    int fluid = 0, j;
    double r2;
    while (fsi_grid_query_next(&q, &j, &r2))
        if (j != i && r2 <= radius2) {
            count++;
            fluid |= p->flags[j] & FLUID_PARTICLE_FLUID;
        }
    v->idle[i] = prune && (p->flags[i] & FLUID_PARTICLE_WALL) && !fluid;
    return v->idle[i] ? 0 : count;
}

/* Pass 2: fills i's row in the grid's order. */
static void fill_row(fluid_verlet *v, const fsi_neighbour_grid *grid, const fluid_particles *p,
                     int i)
{
    if (v->idle[i])
        return;
    fsi_grid_query q;
    fsi_grid_query_begin(&q, grid, p->x + (int64_t)i * FSI_DIM, v->radius);
    const double radius2 = v->radius * v->radius;
    int64_t e = v->offset[i];
    int j;
    double r2;
    while (fsi_grid_query_next(&q, &j, &r2))
        if (j != i && r2 <= radius2)
            v->candidate[e++] = j;
}

int fluid_verlet_build(fluid_verlet *v, const fsi_neighbour_grid *grid, const fluid_particles *p,
                      double radius, int prune_idle_walls)
{
    const int n = p->n;
    v->n = 0;
    if (grid->n != n || n < 0 || reserve(v, n, 0) != 0)
        return -1;
    v->radius = radius;
    v->periodic = grid->periodic;
    const int parallel = n >= FLUID_PARALLEL_MIN_PARTICLES;
    int64_t *offset = v->offset;
    offset[0] = 0;
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (parallel)
    for (int i = 0; i < n; i++)
        offset[i + 1] = row_length(v, grid, p, i, prune_idle_walls);
    for (int i = 0; i < n; i++)
        offset[i + 1] += offset[i];
    if (reserve(v, n, offset[n]) != 0)
        return -1;
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (parallel)
    for (int i = 0; i < n; i++)
        fill_row(v, grid, p, i);
    for (int64_t k = 0; k < (int64_t)n * FSI_DIM; k++)
        v->x_built[k] = p->x[k];
    v->n = n;
    v->builds++;
    return 0;
}

/* Whether every particle is within skin / 2 of where it was at the last build (a
 * little less, so that round-off in the distances cannot lose a pair). False for a
 * non-finite position. */
static int still_valid(const fluid_verlet *v, const fluid_particles *p)
{
    const int n = p->n;
    const double limit2 = 0.999 * 0.25 * v->skin * v->skin;
    double largest = 0.0;
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (n >= FLUID_PARALLEL_MIN_PARTICLES) \
    reduction(max : largest)
    for (int i = 0; i < n; i++) {
        double d2 = 0.0;
        for (int d = 0; d < FSI_DIM; d++) {
            const double dx = p->x[(int64_t)i * FSI_DIM + d] - v->x_built[(int64_t)i * FSI_DIM + d];
            d2 += dx * dx;
        }
        /* NaN never compares: !(d2 <= largest) keeps it. */
        largest = !(d2 <= largest) ? (isnan(d2) ? INFINITY : d2) : largest;
    }
    return largest < limit2;
}

void fluid_verlet_invalidate(fluid_verlet *v)
{
    v->builds = 0;
}

int fluid_verlet_update(fluid_verlet *v, const fluid_particles *p, double support, double skin)
{
    if (v->builds > 0 && v->n == p->n && v->support == support && v->skin == skin &&
        still_valid(v, p))
        return 0;
    v->support = support;
    v->skin = skin;
    if (fsi_grid_build(&v->grid, p->x, p->n, support + skin) != 0 ||
        fluid_verlet_build(v, &v->grid, p, support + skin, 1) != 0)
        return -1;
    return 1;
}

/* The scalars of the lists (no padding: the state is compared and written byte for
 * byte). */
typedef struct {
    int64_t n, builds, periodic_on[FSI_DIM];
    double radius, support, skin, periodic_lo[FSI_DIM], periodic_length[FSI_DIM];
} verlet_header;

int fluid_verlet_save(const fluid_verlet *v, fsi_state *st, const char *prefix)
{
    verlet_header h;
    memset(&h, 0, sizeof h);
    h.n = v->builds > 0 ? v->n : 0;
    h.builds = v->builds > 0 ? v->builds : 0;
    h.radius = v->radius;
    h.support = v->support;
    h.skin = v->skin;
    for (int d = 0; d < FSI_DIM; d++) {
        h.periodic_on[d] = v->periodic.on[d];
        h.periodic_lo[d] = v->periodic.lo[d];
        h.periodic_length[d] = v->periodic.length[d];
    }
    fluid_state_put(st, prefix, "header", &h, sizeof h);
    if (h.builds > 0) {
        const size_t n = (size_t)v->n;
        fluid_state_put(st, prefix, "offset", v->offset, (n + 1) * sizeof *v->offset);
        fluid_state_put(st, prefix, "candidate", v->candidate,
                        (size_t)v->offset[n] * sizeof *v->candidate);
        fluid_state_put(st, prefix, "idle", v->idle, n * sizeof *v->idle);
        fluid_state_put(st, prefix, "x_built", v->x_built, n * FSI_DIM * sizeof *v->x_built);
    }
    return st->failed ? -1 : 0;
}

int fluid_verlet_restore(fluid_verlet *v, const fsi_state *st, const char *prefix)
{
    verlet_header h;
    if (fluid_state_get(st, prefix, "header", &h, sizeof h) != 0 || h.n < 0 || h.n > INT32_MAX)
        return -1;
    v->radius = h.radius;
    v->support = h.support;
    v->skin = h.skin;
    for (int d = 0; d < FSI_DIM; d++) {
        v->periodic.on[d] = (int)h.periodic_on[d];
        v->periodic.lo[d] = h.periodic_lo[d];
        v->periodic.length[d] = h.periodic_length[d];
    }
    if (h.builds == 0) {
        v->builds = 0;      /* the next update rebuilds, as it would have */
        return 0;
    }
    const int n = (int)h.n;
    const size_t pairs = fluid_state_size(st, prefix, "candidate");
    if (pairs == (size_t)-1 || reserve(v, n, (int64_t)(pairs / sizeof *v->candidate)) != 0 ||
        fluid_state_get(st, prefix, "offset", v->offset, ((size_t)n + 1) * sizeof *v->offset) != 0 ||
        fluid_state_get(st, prefix, "candidate", v->candidate, pairs) != 0 ||
        fluid_state_get(st, prefix, "idle", v->idle, (size_t)n * sizeof *v->idle) != 0 ||
        fluid_state_get(st, prefix, "x_built", v->x_built,
                        (size_t)n * FSI_DIM * sizeof *v->x_built) != 0) {
        v->n = 0;
        v->builds = 0;
        return -1;
    }
    v->n = n;
    v->builds = h.builds;
    return 0;
}
