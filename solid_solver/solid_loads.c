/* Prescribed loads of load regions (solid_loads.h). */
#include "solid_loads.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int solid_loads_init(solid_loads *l, const solid_geometry *g, const solid_particles *p,
                     char *msg, size_t msg_size)
{
    memset(l, 0, sizeof *l);
    int n = 0;
    for (int r = 0; r < g->n_regions; r++)
        n += g->regions[r].action == SOLID_REGION_LOAD;
    if (n == 0)
        return 0;
    l->regions = calloc((size_t)n, sizeof *l->regions);
    if (!l->regions)
        goto out_of_memory;
    for (int r = 0; r < g->n_regions; r++) {
        const solid_region *reg = &g->regions[r];
        if (reg->action != SOLID_REGION_LOAD)
            continue;
        solid_load_region *lr = &l->regions[l->n_regions++];
        lr->section = reg->section;
        lr->ramp_time = reg->ramp_time;
        lr->n = solid_region_select(g, r, p, NULL);
        if (lr->n == 0) {
            snprintf(msg, msg_size, "[%s] selects no particle: its load has nowhere to go",
                     reg->section);
            solid_loads_free(l);
            return -1;
        }
        lr->index = malloc((size_t)lr->n * sizeof *lr->index);
        if (!lr->index)
            goto out_of_memory;
        solid_region_select(g, r, p, lr->index);
        for (int d = 0; d < FSI_DIM; d++)
            lr->each[d] = reg->force[d] / lr->n;
    }
    return 0;

out_of_memory:
    solid_loads_free(l);
    snprintf(msg, msg_size, "out of memory for the load regions");
    return -1;
}

void solid_loads_free(solid_loads *l)
{
    for (int r = 0; r < l->n_regions; r++)
        free(l->regions[r].index);
    free(l->regions);
    memset(l, 0, sizeof *l);
}

double solid_load_ramp(double t, double ramp_time)
{
    if (!(ramp_time > 0.0) || t >= ramp_time)
        return 1.0;
    return t > 0.0 ? t / ramp_time : 0.0;
}

void solid_loads_add(const solid_loads *l, double t, double *force)
{
    for (int r = 0; r < l->n_regions; r++) {
        const solid_load_region *lr = &l->regions[r];
        double s = solid_load_ramp(t, lr->ramp_time);
        for (int j = 0; j < lr->n; j++)
            for (int d = 0; d < FSI_DIM; d++)
                force[lr->index[j] * FSI_DIM + d] += s * lr->each[d];
    }
}

void solid_loads_total(const solid_loads *l, double t, double *total)
{
    for (int d = 0; d < FSI_DIM; d++)
        total[d] = 0.0;
    for (int r = 0; r < l->n_regions; r++) {
        double s = solid_load_ramp(t, l->regions[r].ramp_time);
        for (int d = 0; d < FSI_DIM; d++)
            total[d] += s * l->regions[r].each[d] * l->regions[r].n;
    }
}
