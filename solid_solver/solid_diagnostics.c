#include "solid_diagnostics.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "solid_integrate.h"
#include "units.h"

/* The columns before the blocks' (docs/output.md lists them with their meaning). */
static const char *const fixed_columns[] = {
#define J "[" FSI_UNIT_ENERGY "]"
    "window", "dt [s]", "substeps", "step [s]", "kinetic_energy " J, "strain_energy " J,
    "potential_energy " J, "external_work " J, "interface_work " J,
    "interface_work_at_sent " J, "impedance_work " J, "max_speed [m/s]",
#undef J
};
enum { N_FIXED = sizeof fixed_columns / sizeof fixed_columns[0] };

/* Per block: the force's components, then the moment's (one in 2D, about z). */
#define MOMENT_COMPONENTS (FSI_DIM == 2 ? 1 : 3)
enum { PER_BLOCK = FSI_DIM + MOMENT_COMPONENTS };

static int n_columns(const solid_diagnostics *d)
{
    return N_FIXED + PER_BLOCK * d->n_blocks;
}

/* "NAME" of the section "solid.block NAME". */
static const char *block_name(const char *section)
{
    const char *space = strrchr(section, ' ');
    return space ? space + 1 : section;
}

/* The header's column names into names[n_columns]; the block names are written into
 * text (freed by the caller). 0, or -1 when memory runs out. */
static int column_names(const solid_diagnostics *d, const solid_geometry *g, char **names,
                        char **text)
{
    static const char axis[] = "xyz";
    const int n = n_columns(d);
    *text = malloc((size_t)(n > 0 ? n : 1) * 96);
    if (!*text)
        return -1;
    for (int k = 0; k < N_FIXED; k++)
        names[k] = (char *)fixed_columns[k];
    for (int b = 0; b < d->n_blocks; b++)
        for (int c = 0; c < PER_BLOCK; c++) {
            const int k = N_FIXED + b * PER_BLOCK + c;
            char *name = *text + (size_t)k * 96;
            if (c < FSI_DIM)
                snprintf(name, 96, "%.60s.force_%c [" FSI_UNIT_FORCE "]", block_name(g->blocks[b].section),
                         axis[c]);
            else
                snprintf(name, 96, "%.60s.moment_%c [" FSI_UNIT_MOMENT "]", block_name(g->blocks[b].section),
                         FSI_DIM == 2 ? 'z' : axis[c - FSI_DIM]);
            names[k] = name;
        }
    return 0;
}

int solid_diagnostics_open(solid_diagnostics *d, const solid_geometry *g, const char *dir,
                           const char *name, off_t resume, char *msg, size_t msg_size)
{
    d->n_blocks = g->n_blocks;
    const int n = n_columns(d);
    d->block_sums = calloc((size_t)(d->n_blocks > 0 ? d->n_blocks : 1) * PER_BLOCK,
                           sizeof *d->block_sums);
    char **names = malloc((size_t)n * sizeof *names);
    char *text = NULL;
    if (!d->block_sums || !names || column_names(d, g, names, &text) != 0) {
        free(names);
        snprintf(msg, msg_size, "out of memory for the diagnostics of %d blocks", d->n_blocks);
        return -1;
    }
    const int rc = fsi_diagnostics_csv_open(&d->file, dir, name, n, names, resume, msg,
                                            msg_size);
    free(names);
    free(text);
    return rc;
}

/* The fluid's force on each block and its moment about the origin into block_sums. */
static void block_loads(solid_diagnostics *d, const solid_particles *p, const double *force)
{
    memset(d->block_sums, 0, (size_t)d->n_blocks * PER_BLOCK * sizeof *d->block_sums);
    for (int i = 0; i < p->n; i++) {
        const int b = p->block[i];
        if (b < 0 || b >= d->n_blocks)
            continue;
        double *sum = &d->block_sums[b * PER_BLOCK];
        const double *f = &force[i * FSI_DIM], *x = &p->x[i * FSI_DIM];
        for (int c = 0; c < FSI_DIM; c++)
            sum[c] += f[c];
#if FSI_DIM == 2
        sum[2] += x[0] * f[1] - x[1] * f[0];
#else
        sum[3] += x[1] * f[2] - x[2] * f[1];
        sum[4] += x[2] * f[0] - x[0] * f[2];
        sum[5] += x[0] * f[1] - x[1] * f[0];
#endif
    }
}

int solid_diagnostics_write(solid_diagnostics *d, double t, const solid_particles *p,
                            const double *gravity, const solid_window_summary *w, char *msg,
                            size_t msg_size)
{
    const int n = n_columns(d);
    double *values = malloc((size_t)n * sizeof *values);
    if (!values) {
        snprintf(msg, msg_size, "out of memory for a diagnostics row");
        return -1;
    }
    const double fixed[N_FIXED] = {
        w->window, w->dt, (double)w->substeps,
        w->substeps > 0 ? w->dt / (double)w->substeps : 0.0, w->kinetic, w->strain,
        solid_potential_energy(p, gravity), w->external_work, w->interface_work,
        w->interface_work_at_sent, w->impedance_work, w->max_speed,
    };
    memcpy(values, fixed, sizeof fixed);
    block_loads(d, p, w->fluid_force);
    memcpy(values + N_FIXED, d->block_sums, (size_t)d->n_blocks * PER_BLOCK * sizeof *values);
    const int rc = fsi_diagnostics_csv_row(&d->file, t, values, msg, msg_size);
    free(values);
    return rc;
}

off_t solid_diagnostics_bytes(const solid_diagnostics *d)
{
    return fsi_diagnostics_csv_bytes(&d->file);
}

void solid_diagnostics_close(solid_diagnostics *d)
{
    fsi_diagnostics_csv_close(&d->file);
    free(d->block_sums);
    d->block_sums = NULL;
}
