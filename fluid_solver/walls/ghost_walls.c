/* Wall particles from the fluid around them (ghost_walls.h, 000 Eqs. 50-54). */
#include "ghost_walls.h"

#include <math.h>
#include <string.h>

#include "fluid_parallel.h"

void ghost_walls_update(const fluid_pairs *pairs, const tait_eos *eos, const double *gravity,
                       const unsigned char *free_slip, fluid_particles *p,
                       double *velocity_for_viscosity)
{
    const int n = p->n;
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int s = 0; s < n; s++) {
        double *vv = &velocity_for_viscosity[s * FSI_DIM];
        if (!(p->flags[s] & (FLUID_PARTICLE_WALL | FLUID_PARTICLE_MOVING_BOUNDARY))) {
            memcpy(vv, &p->v[s * FSI_DIM], FSI_DIM * sizeof *vv);
            continue;
        }
        double sum_w = 0.0, sum_pw = 0.0, head[FSI_DIM] = {0}, v_mean[FSI_DIM] = {0};
        double toward[FSI_DIM] = {0};
        for (int64_t k = pairs->offset[s]; k < pairs->offset[s + 1]; k++) {
            const int f = pairs->neighbour[k];
            if (!(p->flags[f] & FLUID_PARTICLE_FLUID))
                continue;
            const double w = pairs->w[k];
            double xsf[FSI_DIM]; /* x_f - x_S */
            fluid_pair_vector(pairs, p->x, s, f, xsf);
            sum_w += w;
            sum_pw += p->pressure[f] * w;
            for (int d = 0; d < FSI_DIM; d++) {
                head[d] -= p->density[f] * xsf[d] * w;
                toward[d] += xsf[d] * w;
                v_mean[d] += p->v[f * FSI_DIM + d] * w;
            }
        }
        double pressure = 0.0;
        if (sum_w > 0.0) {
            /* (g - a_S) of 000 Eq. 52; a_S = 0 for a fixed wall. */
            pressure = sum_pw;
            for (int d = 0; d < FSI_DIM; d++) {
                const double a_s = p->boundary_acceleration[s * FSI_DIM + d];
                pressure += (gravity[d] - a_s) * head[d];
                v_mean[d] /= sum_w;
            }
            pressure /= sum_w;
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
}
