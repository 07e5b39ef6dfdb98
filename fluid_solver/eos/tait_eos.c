/* The fluid particles' pressure and volume from their density (tait_eos.h). */
#include "tait_eos.h"

#include "fluid_parallel.h"

void tait_eos_update_fluid(const tait_eos *e, fluid_particles *p, int tension)
{
    const int n = p->n;
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++)
        if (p->flags[i] & FLUID_PARTICLE_FLUID) {
            if (!tension && p->density[i] < e->rho0)
                p->density[i] = e->rho0;
            p->pressure[i] = tait_eos_pressure(e, p->density[i]);
            p->volume[i] = p->mass[i] / p->density[i];
        }
}
