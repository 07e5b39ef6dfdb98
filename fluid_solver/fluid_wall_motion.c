/* Moving wall particles (fluid_wall_motion.h). */
#include "fluid_wall_motion.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fluid_state.h"
#include "lattice_box.h"

int fluid_wall_motion_init(fluid_wall_motion *w, const fluid_geometry *g,
                           const fluid_particles *p, char *msg, size_t msg_size)
{
    memset(w, 0, sizeof *w);
    int moving = 0, i = 0, same = 1;
    const fluid_motion *first = NULL;
    for (int b = 0; b < g->n_boxes; b++) {
        const fluid_box *box = &g->boxes[b];
        if (!box->is_wall || box->motion.kind == FLUID_MOTION_NONE)
            continue;
        moving += (int)fluid_box_points(box);
        if (!first)
            first = &box->motion;
        same = same && fluid_motion_same(first, &box->motion);
    }
    if (moving == 0)
        return 0;
    w->particle = malloc((size_t)moving * sizeof *w->particle);
    w->law = malloc((size_t)moving * sizeof *w->law);
    w->x_start = malloc((size_t)moving * FSI_DIM * sizeof *w->x_start);
    if (!w->particle || !w->law || !w->x_start) {
        fluid_wall_motion_free(w);
        snprintf(msg, msg_size, "out of memory for %d moving wall particles", moving);
        return -1;
    }
    /* Particles follow the boxes in order (fluid_geometry_build). */
    for (int b = 0; b < g->n_boxes; b++) {
        const fluid_box *box = &g->boxes[b];
        const long count = (long)fluid_box_points(box);
        if (!box->is_wall || box->motion.kind == FLUID_MOTION_NONE) {
            i += (int)count;
            continue;
        }
        for (long j = 0; j < count; j++, i++) {
            const int k = w->n_moving++;
            w->particle[k] = i;
            w->law[k] = &box->motion;
            memcpy(&w->x_start[k * FSI_DIM], &p->x[i * FSI_DIM], FSI_DIM * sizeof *p->x);
        }
    }
    w->tank = same ? first : NULL;
    return 0;
}

void fluid_wall_motion_renumber(fluid_wall_motion *w, const int *new_index)
{
    for (int k = 0; k < w->n_moving; k++)
        w->particle[k] = new_index[w->particle[k]];
}

void fluid_wall_motion_apply(fluid_wall_motion *w, double t, fluid_particles *p)
{
    for (int k = 0; k < w->n_moving; k++) {
        const int i = w->particle[k];
        double s[FSI_DIM];
        fluid_motion_at(w->law[k], t, s, &p->v[i * FSI_DIM],
                        &p->boundary_acceleration[i * FSI_DIM]);
        for (int d = 0; d < FSI_DIM; d++)
            p->x[i * FSI_DIM + d] = w->x_start[k * FSI_DIM + d] + s[d];
    }
}

void fluid_wall_motion_widen(const fluid_wall_motion *w, double *box_min, double *box_max)
{
    for (int d = 0; d < FSI_DIM; d++) {
        double reach = 0.0;
        for (int k = 0; k < w->n_moving; k++)
            reach = fmax(reach, fluid_motion_reach(w->law[k], d));
        box_min[d] -= reach;
        box_max[d] += reach;
    }
}

double fluid_wall_motion_power(const fluid_wall_motion *w, double t, const fluid_particles *p,
                               const double *dv_dt, const double *gravity)
{
    if (w->n_moving == 0)
        return 0.0;
    if (!w->tank)
        return NAN;
    double v[FSI_DIM], force[FSI_DIM] = {0};
    fluid_motion_at(w->tank, t, NULL, v, NULL);
    for (int i = 0; i < p->n; i++)
        if (p->flags[i] & FLUID_PARTICLE_FLUID)
            for (int d = 0; d < FSI_DIM; d++)
                force[d] += p->mass[i] * (dv_dt[i * FSI_DIM + d] - gravity[d]);
    double power = 0.0;
    for (int d = 0; d < FSI_DIM; d++)
        power += force[d] * v[d];
    return power;
}

int fluid_wall_motion_save_state(const fluid_wall_motion *w, fsi_state *st, const char *prefix)
{
    return fluid_state_put(st, prefix, "particle", w->particle,
                           (size_t)w->n_moving * sizeof *w->particle);
}

int fluid_wall_motion_restore_state(fluid_wall_motion *w, const fsi_state *st,
                                    const char *prefix)
{
    const size_t bytes = (size_t)w->n_moving * sizeof *w->particle;
    if (bytes == 0)
        return fluid_state_size(st, prefix, "particle") == 0 ? 0 : -1;
    return fluid_state_get(st, prefix, "particle", w->particle, bytes);
}

void fluid_wall_motion_free(fluid_wall_motion *w)
{
    free(w->particle);
    free(w->law);
    free(w->x_start);
    memset(w, 0, sizeof *w);
}
