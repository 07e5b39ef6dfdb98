/* Pressure probes (fluid_probes.h). */
#include "fluid_probes.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int fluid_probes_init(fluid_probes *pr, const fluid_geometry *g, fsi_participant *part,
                      char *msg, size_t msg_size)
{
    memset(pr, 0, sizeof *pr);
    if (g->n_probes == 0)
        return 0;
    pr->point = malloc((size_t)g->n_probes * sizeof *pr->point);
    pr->column = malloc((size_t)g->n_probes * sizeof *pr->column);
    if (!pr->point || !pr->column) {
        fluid_probes_free(pr);
        snprintf(msg, msg_size, "out of memory for the probes");
        return -1;
    }
    for (int q = 0; q < g->n_probes; q++) {
        memcpy(pr->point[q], g->probes[q].point, sizeof pr->point[q]);
        const char *name = fsi_case_object_name(g->probes[q].section);
        char column[160];
        snprintf(column, sizeof column, "%s_p", name ? name : "probe");
        pr->column[q] = fsi_add_probe(part, column);
        if (pr->column[q] < 0) {
            snprintf(msg, msg_size, "[%s]: cannot add the probe column %s (too many probe "
                     "columns?)", g->probes[q].section, column);
            fluid_probes_free(pr);
            return -1;
        }
        pr->n = q + 1;
    }
    return 0;
}

void fluid_probes_set(const fluid_probes *pr, const fluid_particles *p, const double *grad_p,
                      fsi_participant *part)
{
    for (int q = 0; q < pr->n; q++) {
        int best = -1;
        double best_d2 = INFINITY;
        for (int i = 0; i < p->n; i++) {
            if (!(p->flags[i] & FLUID_PARTICLE_FLUID))
                continue;
            double d2 = 0.0;
            for (int d = 0; d < FSI_DIM; d++) {
                double e = p->x[i * FSI_DIM + d] - pr->point[q][d];
                d2 += e * e;
            }
            if (d2 < best_d2) {
                best_d2 = d2;
                best = i;
            }
        }
        double value = NAN;
        if (best >= 0) {
            value = p->pressure[best];
            for (int d = 0; d < FSI_DIM; d++)
                value += grad_p[best * FSI_DIM + d] * (pr->point[q][d] - p->x[best * FSI_DIM + d]);
        }
        fsi_set_probe(part, pr->column[q], value);
    }
}

void fluid_probes_free(fluid_probes *pr)
{
    free(pr->point);
    free(pr->column);
    memset(pr, 0, sizeof *pr);
}
