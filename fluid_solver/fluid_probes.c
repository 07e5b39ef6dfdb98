/* Pressure and free-surface elevation probes (fluid_probes.h). */
#include "fluid_probes.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "small_tensor.h"

int fluid_probes_init(fluid_probes *pr, const fluid_geometry *g, fsi_participant *part,
                      char *msg, size_t msg_size)
{
    memset(pr, 0, sizeof *pr);
    pr->spacing = g->spacing;
    if (g->n_probes == 0)
        return 0;
    const size_t n = (size_t)g->n_probes;
    pr->point = malloc(n * sizeof *pr->point);
    pr->column = malloc(n * sizeof *pr->column);
    pr->elevation = malloc(n * sizeof *pr->elevation);
    pr->follow = malloc(n * sizeof *pr->follow);
    if (!pr->point || !pr->column || !pr->elevation || !pr->follow) {
        fluid_probes_free(pr);
        snprintf(msg, msg_size, "out of memory for the probes");
        return -1;
    }
    for (int q = 0; q < g->n_probes; q++) {
        const fluid_probe_point *src = &g->probes[q];
        memcpy(pr->point[q], src->point, sizeof pr->point[q]);
        pr->elevation[q] = src->elevation;
        pr->follow[q] = src->follow_box >= 0 ? &g->boxes[src->follow_box].motion : NULL;
        const char *name = fsi_case_object_name(src->section);
        char column[160];
        /* "NAME_p [Pa]": the unit goes to probes.csv's units line. */
        snprintf(column, sizeof column, "%s_%s", name ? name : "probe",
                 src->elevation ? "eta [m]" : "p [Pa]");
        pr->column[q] = fsi_add_probe(part, column);
        if (pr->column[q] < 0) {
            snprintf(msg, msg_size, "[%s]: cannot add the probe column %s (too many probe "
                     "columns?)", src->section, column);
            fluid_probes_free(pr);
            return -1;
        }
        pr->n = q + 1;
    }
    return 0;
}

static double pressure_at(const fluid_particles *p, const double *grad_p, const double *x)
{
    int best = -1;
    double best_d2 = INFINITY;
    for (int i = 0; i < p->n; i++) {
        if (!(p->flags[i] & FLUID_PARTICLE_FLUID))
            continue;
        double e[FSI_DIM];
        for (int d = 0; d < FSI_DIM; d++)
            e[d] = p->x[i * FSI_DIM + d] - x[d];
        const double d2 = fsi_vec_dot(e, e);
        if (d2 < best_d2) {
            best_d2 = d2;
            best = i;
        }
    }
    if (best < 0)
        return NAN;
    double value = p->pressure[best];
    for (int d = 0; d < FSI_DIM; d++)
        value += grad_p[best * FSI_DIM + d] * (x[d] - p->x[best * FSI_DIM + d]);
    return value;
}

static double elevation_at(const fluid_particles *p, double dx, const double *x)
{
    const int up = FSI_DIM - 1;
    double top = -INFINITY;
    for (int i = 0; i < p->n; i++) {
        if (!(p->flags[i] & FLUID_PARTICLE_FLUID))
            continue;
        int near = 1;
        for (int d = 0; d < up; d++)
            near = near && fabs(p->x[i * FSI_DIM + d] - x[d]) <= dx;
        if (near)
            top = fmax(top, p->x[i * FSI_DIM + up]);
    }
    return isfinite(top) ? top + 0.5 * dx - x[up] : NAN;
}

void fluid_probes_set(const fluid_probes *pr, const fluid_particles *p, const double *grad_p,
                      double t, fsi_participant *part)
{
    for (int q = 0; q < pr->n; q++) {
        double x[FSI_DIM], shift[FSI_DIM] = {0};
        if (pr->follow[q])
            fluid_motion_at(pr->follow[q], t, shift, NULL, NULL);
        for (int d = 0; d < FSI_DIM; d++)
            x[d] = pr->point[q][d] + shift[d];
        fsi_set_probe(part, pr->column[q], pr->elevation[q] ? elevation_at(p, pr->spacing, x)
                                                           : pressure_at(p, grad_p, x));
    }
}

void fluid_probes_free(fluid_probes *pr)
{
    free(pr->point);
    free(pr->column);
    free(pr->elevation);
    free(pr->follow);
    memset(pr, 0, sizeof *pr);
}
