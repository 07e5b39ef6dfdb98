/* Probes following particles (solid_probes.h). */
#include "solid_probes.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char axis_name[3] = {'x', 'y', 'z'};

int solid_probes_init(solid_probes *pr, const solid_geometry *g, const solid_particles *p,
                      fsi_participant *part, char *msg, size_t msg_size)
{
    memset(pr, 0, sizeof *pr);
    if (g->n_probes == 0)
        return 0;
    pr->particle = malloc((size_t)g->n_probes * sizeof *pr->particle);
    pr->column = malloc((size_t)g->n_probes * sizeof *pr->column);
    if (!pr->particle || !pr->column) {
        solid_probes_free(pr);
        snprintf(msg, msg_size, "out of memory for the probes");
        return -1;
    }
    for (int q = 0; q < g->n_probes; q++) {
        const solid_probe_point *sp = &g->probes[q];
        double distance;
        int i = solid_nearest_particle(p, sp->point, &distance);
        if (i < 0 || distance > p->spacing * (1.0 + SOLID_GEOMETRY_TOL)) {
            snprintf(msg, msg_size, "[%s] point: no particle within one spacing (nearest at "
                     "%g m)", sp->section, distance);
            solid_probes_free(pr);
            return -1;
        }
        pr->particle[q] = i;
        for (int k = 0; k < 2 * FSI_DIM; k++)
            pr->column[q][k] = -1;
        pr->n = q + 1;
        if (!part)
            continue;
        const char *name = fsi_case_object_name(sp->section);
        for (int quantity = 0; quantity < 2; quantity++)
            for (int d = 0; d < FSI_DIM; d++) {
                char column[160];
                /* "NAME_ux [m]": the unit goes to probes.csv's units line. */
                snprintf(column, sizeof column, "%s_%c%c %s", name ? name : "probe",
                         quantity ? 'v' : 'u', axis_name[d], quantity ? "[m/s]" : "[m]");
                int index = fsi_add_probe(part, column);
                if (index < 0) {
                    snprintf(msg, msg_size, "[%s]: cannot add the probe column %s (too many "
                             "probe columns?)", sp->section, column);
                    solid_probes_free(pr);
                    return -1;
                }
                pr->column[q][quantity * FSI_DIM + d] = index;
            }
    }
    return 0;
}

void solid_probes_set(const solid_probes *pr, const solid_particles *p, fsi_participant *part)
{
    for (int q = 0; q < pr->n; q++) {
        int i = pr->particle[q];
        for (int d = 0; d < FSI_DIM; d++) {
            if (pr->column[q][d] >= 0)
                fsi_set_probe(part, pr->column[q][d],
                              p->x[i * FSI_DIM + d] - p->x0[i * FSI_DIM + d]);
            if (pr->column[q][FSI_DIM + d] >= 0)
                fsi_set_probe(part, pr->column[q][FSI_DIM + d], p->v[i * FSI_DIM + d]);
        }
    }
}

void solid_probes_free(solid_probes *pr)
{
    free(pr->particle);
    free(pr->column);
    memset(pr, 0, sizeof *pr);
}
