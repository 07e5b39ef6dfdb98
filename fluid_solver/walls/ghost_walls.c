/* Wall particles from the fluid around them (ghost_walls.h, 000 Eqs. 50-54). */
#include "ghost_walls.h"

#include <math.h>
#include <string.h>

#include "fluid_parallel.h"

void ghost_wall_set(const ghost_wall_sums *g, int s, const tait_eos *eos,
                    const double *gravity, const unsigned char *free_slip,
                    fluid_particles *p, double *velocity_for_viscosity)
{
    double *vv = &velocity_for_viscosity[s * FSI_DIM];
    double v_mean[FSI_DIM], toward[FSI_DIM];
    memcpy(v_mean, g->v_mean, sizeof v_mean);
    memcpy(toward, g->toward, sizeof toward);
    double pressure = 0.0;
    if (g->sum_w > 0.0) {
        /* (g - a_S) of 000 Eq. 52; a_S = 0 for a fixed wall. */
        pressure = g->sum_pw;
        for (int d = 0; d < FSI_DIM; d++) {
            const double a_s = p->boundary_acceleration[s * FSI_DIM + d];
            pressure += (gravity[d] - a_s) * g->head[d];
            v_mean[d] /= g->sum_w;
        }
        pressure /= g->sum_w;
    } else {
        /* No fluid to interpolate: the wall shows its own velocity, so that the
         * viscous stress of a scheme that differentiates the walls' velocities
         * (WCSPH's tau at a wall particle) sees a wall moving rigidly, not one at
         * twice its speed (a uniform translation must change nothing). */
        memcpy(v_mean, &p->v[s * FSI_DIM], sizeof v_mean);
    }
    p->pressure[s] = pressure = fmax(pressure, 0.0);
    p->density[s] = tait_eos_density(eos, pressure);
    p->mass[s] = p->density[s] * p->volume[s];
    if ((p->flags[s] & FLUID_PARTICLE_WALL) && free_slip && free_slip[s]) {
        double norm = 0.0, vn = 0.0;
        for (int d = 0; d < FSI_DIM; d++)
            norm += toward[d] * toward[d];
        norm = sqrt(norm);
        for (int d = 0; d < FSI_DIM; d++) {
            toward[d] = norm > 0.0 ? toward[d] / norm : 0.0;
            vn += (v_mean[d] - p->v[s * FSI_DIM + d]) * toward[d];
        }
        for (int d = 0; d < FSI_DIM; d++)
            vv[d] = v_mean[d] - 2.0 * vn * toward[d];
    } else {
        for (int d = 0; d < FSI_DIM; d++)
            vv[d] = 2.0 * p->v[s * FSI_DIM + d] - v_mean[d];
    }
}

void ghost_walls_update(const fluid_rows *rows, const fsi_periodic *per, const tait_eos *eos,
                        const double *gravity, const unsigned char *free_slip, fluid_particles *p,
                        double *velocity_for_viscosity)
{
    const int n = p->n;
    const fsi_periodic *axes = per && fsi_periodic_any(per) ? per : NULL;
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int s = 0; s < n; s++) {
        if (!(p->flags[s] & (FLUID_PARTICLE_WALL | FLUID_PARTICLE_MOVING_BOUNDARY))) {
            memcpy(&velocity_for_viscosity[s * FSI_DIM], &p->v[s * FSI_DIM],
                   FSI_DIM * sizeof *velocity_for_viscosity);
            continue;
        }
        ghost_wall_sums g = {0};
        for (int64_t k = rows->split[s]; k < rows->boundary_end[s]; k++) {
            const int f = rows->pair[k];
            if (!(p->flags[f] & FLUID_PARTICLE_FLUID))
                continue;
            double xsf[FSI_DIM]; /* x_f - x_S */
            fluid_pair_vector_r2(axes, p->x, s, f, xsf);
            ghost_wall_sums_add(&g, p, f, rows->f[k], xsf);
        }
        ghost_wall_set(&g, s, eos, gravity, free_slip, p, velocity_for_viscosity);
    }
}
