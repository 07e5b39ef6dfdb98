/* The loads the fluid publishes (fluid_coupling.c): over a window of uneven steps h_n
 * with known boundary forces F_n, the force sent for every solid particle is the mean
 * sum_n h_n F_n / sum_n h_n, in the order the solid sent its particles, to round-off
 * (1e-14 relative: a handful of additions); the impulse the solid must total
 * (impulse_sent) is sum_n h_n sum_B F_n. A load scaled on the way (the mutant
 * `impulse += 0.95 * h * f` of bench/mutations.list) is 5 % off. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fluid_coupling.h"
#include "fluid_particles.h"

#include "unit_check.h"
#include "unit_random.h"

enum { N_FIXED = 4, N_SOLID = 6, N_STEPS = 7 };

int main(void)
{
    uint64_t rng = 24;
    const double rho0 = 1000.0;
    fluid_particles p;
    if (fluid_particles_alloc(&p, N_FIXED, 0.01) != 0)
        return 2;
    for (int i = 0; i < N_FIXED; i++) {
        p.id[i] = i;
        p.flags[i] = i % 2 ? FLUID_PARTICLE_WALL : FLUID_PARTICLE_FLUID;
        p.x[i * FSI_DIM] = 0.01 * i;
    }
    /* The solid's interface particles, ids not in order (the loads go back in the
     * order they came). */
    int32_t id[N_SOLID];
    double x[N_SOLID * FSI_DIM], v[N_SOLID * FSI_DIM], a[N_SOLID * FSI_DIM], vol[N_SOLID],
        rho[N_SOLID];
    for (int k = 0; k < N_SOLID; k++) {
        id[k] = 100 + (5 * k) % N_SOLID;
        vol[k] = 1e-4;
        rho[k] = 2700.0;
        for (int d = 0; d < FSI_DIM; d++) {
            x[k * FSI_DIM + d] = 0.5 + 0.01 * k + 0.003 * d;
            v[k * FSI_DIM + d] = unit_uniform(&rng) - 0.5;
            a[k * FSI_DIM + d] = 0.0;
        }
    }
    fsi_interface solid = {.n = N_SOLID, .id = id, .position = x, .velocity = v,
                           .acceleration = a, .volume = vol, .density = rho};
    fluid_coupling c;
    fluid_coupling_init(&c, N_FIXED, rho0 * 30.0);
    char msg[256];
    CHECK(fluid_coupling_start_window(&c, &p, &solid, rho0, 0.0, msg, sizeof msg) == 0,
          "start of the window: %s", msg);
    CHECK(p.n == N_FIXED + N_SOLID, "boundary not appended: %d particles", p.n);

    /* Uneven steps (a factor of 5 between them) and forces of both signs on every
     * particle, the fixed particles' entries included (they must not count). */
    double impulse[N_SOLID * FSI_DIM] = {0}, total[FSI_DIM] = {0}, window = 0.0;
    double *force = calloc((size_t)p.n * FSI_DIM, sizeof *force);
    for (int n = 0; n < N_STEPS; n++) {
        const double h = 1e-4 * (1.0 + 4.0 * unit_uniform(&rng));
        for (int k = 0; k < p.n * FSI_DIM; k++)
            force[k] = 200.0 * (unit_uniform(&rng) - 0.3);
        fluid_coupling_add_loads(&c, &p, force, h);
        for (int k = 0; k < N_SOLID * FSI_DIM; k++) {
            impulse[k] += h * force[N_FIXED * FSI_DIM + k];
            total[k % FSI_DIM] += h * force[N_FIXED * FSI_DIM + k];
        }
        window += h;
    }
    CHECK(fluid_coupling_window_loads(&c, &p, window) == 0, "no memory for the loads");
    double worst = 0.0, scale = 0.0;
    int order = 1;
    for (int k = 0; k < N_SOLID; k++) {
        order = order && c.out_id[k] == id[k];
        for (int d = 0; d < FSI_DIM; d++) {
            const double expected = impulse[k * FSI_DIM + d] / window;
            worst = fmax(worst, fabs(c.out_force[k * FSI_DIM + d] - expected));
            scale = fmax(scale, fabs(expected));
        }
    }
    double worst_total = 0.0, scale_total = 0.0;
    for (int d = 0; d < FSI_DIM; d++) {
        worst_total = fmax(worst_total, fabs(c.impulse_sent[d] - total[d]));
        scale_total = fmax(scale_total, fabs(total[d]));
    }
    printf("window of %d steps (%.4g s): published mean force off by %.3g of %.4g N, total "
           "impulse off by %.3g of %.4g N s\n", N_STEPS, window, worst, scale, worst_total,
           scale_total);
    CHECK(order, "the loads are not in the order the solid sent its particles");
    CHECK(scale > 0.0 && worst <= 1e-14 * scale, "the published force is not the "
          "accumulated boundary load sum h F / window: off by %.3g N of %.3g N (%.3g %%)",
          worst, scale, 100.0 * worst / scale);
    CHECK(worst_total <= 1e-14 * scale_total, "the total impulse sent is off by %.3g N s of "
          "%.3g N s", worst_total, scale_total);

    free(force);
    fluid_coupling_free(&c);
    fluid_particles_free(&p);
    return unit_check_report("test_fluid_coupling_loads");
}
