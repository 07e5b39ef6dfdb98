/* Fluid leaking through walls (fluid_leak.h). */
#include "fluid_leak.h"

#include <stdlib.h>
#include <string.h>

#include "fluid_parallel.h"
#include "fluid_state.h"

enum { SIDE_UNKNOWN = 0, SIDE_BELOW = 1, SIDE_ABOVE = 2 };

/* The wall box b at time t: where it is drawn, moved by its motion, and its velocity
 * (vel may be NULL). */
static void wall_at(const fluid_box *b, double t, double *lo, double *hi, double *vel)
{
    double s[FSI_DIM];
    fluid_motion_at(&b->motion, t, s, vel, NULL);
    for (int d = 0; d < FSI_DIM; d++) {
        lo[d] = b->shape.min[d] + s[d];
        hi[d] = b->shape.max[d] + s[d];
    }
}

/* Updates the side of x against the wall [lo, hi] along every axis; returns the axis
 * it crossed along (with *upward), or -1. */
static int update_sides(const fluid_leak *l, const double *lo, const double *hi,
                        const double *x, unsigned char *side, int *upward)
{
    int crossed = -1;
    for (int d = 0; d < FSI_DIM; d++) {
        if (l->periodic[d])
            continue;
        int shadow = 1;
        for (int e = 0; e < FSI_DIM && shadow; e++)
            shadow = e == d || l->periodic[e] || (x[e] >= lo[e] && x[e] <= hi[e]);
        if (!shadow) {
            side[d] = SIDE_UNKNOWN;
        } else if (x[d] < lo[d]) {
            if (side[d] == SIDE_ABOVE && x[d] < lo[d] - l->tolerance && crossed < 0) {
                crossed = d;
                *upward = 0;
            } else if (side[d] != SIDE_ABOVE) {
                side[d] = SIDE_BELOW;
            }
        } else if (x[d] > hi[d]) {
            if (side[d] == SIDE_BELOW && x[d] > hi[d] + l->tolerance && crossed < 0) {
                crossed = d;
                *upward = 1;
            } else if (side[d] != SIDE_BELOW) {
                side[d] = SIDE_ABOVE;
            }
        }
        /* Inside the wall's slab the side is kept. */
    }
    return crossed;
}

/* A fluid particle at x (velocity v) inside the wall [lo, hi] (velocity vw), having come
 * in from a known side: back on the face it came through (of the axes it came in along,
 * the one of least depth), its velocity into the wall set to the wall's. Returns 1 when
 * it was moved. */
static int hold_out(const fluid_leak *l, const double *lo, const double *hi, const double *vw,
                    const unsigned char *side, double *x, double *v)
{
    int axis = -1;
    double depth = 0.0;
    for (int d = 0; d < FSI_DIM; d++) {
        if (!l->periodic[d] && !(x[d] > lo[d] && x[d] < hi[d]))
            return 0;   /* not inside */
        const double dd = side[d] == SIDE_BELOW ? x[d] - lo[d]
                          : side[d] == SIDE_ABOVE ? hi[d] - x[d] : -1.0;
        if (dd >= 0.0 && (axis < 0 || dd < depth)) {
            axis = d;
            depth = dd;
        }
    }
    if (axis < 0)
        return 0;       /* inside since the start, or from an unknown side */
    const int below = side[axis] == SIDE_BELOW;
    x[axis] = below ? lo[axis] : hi[axis];
    if (below ? v[axis] > vw[axis] : v[axis] < vw[axis])
        v[axis] = vw[axis];
    return 1;
}

/* Walls whose sides the check follows: axis-aligned boxes. A turned box, disc or
 * polygon has no slabs along the axes to be on one side of. */
static int leak_checked(const fluid_box *b)
{
    return b->is_wall && fsi_shape_is_plain_box(&b->shape);
}

int fluid_leak_init(fluid_leak *l, const fluid_geometry *g, const fsi_periodic *per,
                    double tolerance, const fluid_particles *p, int n, double t)
{
    memset(l, 0, sizeof *l);
    l->geometry = g;
    l->tolerance = tolerance;
    for (int d = 0; d < FSI_DIM; d++)
        l->periodic[d] = per && per->on[d];
    for (int b = 0; b < g->n_boxes; b++)
        l->n_walls += leak_checked(&g->boxes[b]);
    l->n = n;
    if (l->n_walls == 0)
        return 0;
    l->wall = malloc((size_t)l->n_walls * sizeof *l->wall);
    l->box_lo = malloc((size_t)l->n_walls * FSI_DIM * sizeof *l->box_lo);
    l->box_hi = malloc((size_t)l->n_walls * FSI_DIM * sizeof *l->box_hi);
    l->box_v = malloc((size_t)l->n_walls * FSI_DIM * sizeof *l->box_v);
    l->side = calloc((size_t)(n > 0 ? n : 1) * (size_t)l->n_walls * FSI_DIM, 1);
    if (!l->wall || !l->box_lo || !l->box_hi || !l->box_v || !l->side) {
        fluid_leak_free(l);
        return -1;
    }
    for (int b = 0, w = 0; b < g->n_boxes; b++)
        if (leak_checked(&g->boxes[b]))
            l->wall[w++] = b;
    fluid_leak_crossing ignored;
    fluid_leak_check(l, p, t, &ignored);     /* the sides at the start */
    return 0;
}

/* fluid_leak_check, and with x and v (p's own arrays) fluid_leak_hold_and_check. */
static int scan(fluid_leak *l, const fluid_particles *p, double *x, double *v, double t,
                long *held, fluid_leak_crossing *found)
{
    found->particle = -1;
    const int n = l->n, n_walls = l->n_walls;
    if (n_walls == 0)
        return 0;
    double *lo = l->box_lo, *hi = l->box_hi;
    for (int w = 0; w < n_walls; w++)
        wall_at(&l->geometry->boxes[l->wall[w]], t, &lo[w * FSI_DIM], &hi[w * FSI_DIM],
                &l->box_v[w * FSI_DIM]);
    /* One pass over the particles, every wall at each (its sides are its own). The
     * first crossing (by wall, then index) is the one reported, on any number of
     * threads: the smallest key 8 (w n + i) + 2 axis + upward. */
    const long long none = 8LL * n_walls * n;
    long long first = none, moved = 0;
#pragma omp parallel for schedule(static) reduction(min : first) reduction(+ : moved) \
    if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        if (!(p->flags[i] & FLUID_PARTICLE_FLUID))
            continue;
        for (int w = 0; w < n_walls; w++) {
            unsigned char *side = &l->side[((size_t)i * n_walls + w) * FSI_DIM];
            if (x)
                moved += hold_out(l, &lo[w * FSI_DIM], &hi[w * FSI_DIM],
                                  &l->box_v[w * FSI_DIM], side, &x[i * FSI_DIM],
                                  &v[i * FSI_DIM]);
            int upward = 0;
            const int d = update_sides(l, &lo[w * FSI_DIM], &hi[w * FSI_DIM],
                                       &p->x[i * FSI_DIM], side, &upward);
            const long long key = 8LL * ((long long)w * n + i) + 2 * d + upward;
            if (d >= 0 && key < first)
                first = key;
        }
    }
    if (first < none) {
        const long long wi = first / 8;
        const int w = (int)(wi / n), d = (int)(first % 8) / 2, upward = (int)(first % 2);
        *found = (fluid_leak_crossing){(int)(wi % n), l->wall[w], d, upward,
                                       upward ? hi[w * FSI_DIM + d] : lo[w * FSI_DIM + d]};
    }
    if (held)
        *held += moved;
    return found->particle >= 0;
}

int fluid_leak_check(fluid_leak *l, const fluid_particles *p, double t,
                     fluid_leak_crossing *found)
{
    return scan(l, p, NULL, NULL, t, NULL, found);
}

int fluid_leak_hold_and_check(fluid_leak *l, fluid_particles *p, double t, long *held,
                              fluid_leak_crossing *found)
{
    return scan(l, p, p->x, p->v, t, held, found);
}

int fluid_leak_reorder(fluid_leak *l, const int *sorted)
{
    if (l->n_walls == 0)
        return 0;
    const size_t row = (size_t)l->n_walls * FSI_DIM;
    unsigned char *side = malloc((size_t)(l->n > 0 ? l->n : 1) * row);
    if (!side)
        return -1;
    for (int k = 0; k < l->n; k++)
        memcpy(&side[(size_t)k * row], &l->side[(size_t)sorted[k] * row], row);
    free(l->side);
    l->side = side;
    return 0;
}

static size_t side_bytes(const fluid_leak *l)
{
    return l->n_walls > 0 ? (size_t)l->n * (size_t)l->n_walls * FSI_DIM : 0;
}

int fluid_leak_save_state(const fluid_leak *l, fsi_state *st, const char *prefix)
{
    return fluid_state_put(st, prefix, "side", l->side, side_bytes(l));
}

int fluid_leak_restore_state(fluid_leak *l, const fsi_state *st, const char *prefix)
{
    const size_t bytes = side_bytes(l);
    if (bytes == 0)
        return fluid_state_size(st, prefix, "side") == 0 ? 0 : -1;
    return fluid_state_get(st, prefix, "side", l->side, bytes);
}

void fluid_leak_free(fluid_leak *l)
{
    free(l->wall);
    free(l->box_lo);
    free(l->box_hi);
    free(l->box_v);
    free(l->side);
    memset(l, 0, sizeof *l);
}
