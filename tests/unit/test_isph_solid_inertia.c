/* The solid's inertia in ISPH's pressure Poisson equation (isph_ppe.h, boundary_row):
 * a block of water H deep resting on one layer of solid particles that nothing
 * holds up (received velocity and acceleration zero, no load of a last step), one
 * projection. The floor then moves in the equation only by the load the solve gives
 * it over its mass, so water and floor fall together, and the load on the floor per
 * unit length is that of a water column of mass m_w per unit area on a free plate of
 * mass M per unit area:
 *   F / L = g m_w M / (m_w + M),   M = rho_S dx max(1, depth / dx),
 * with depth the key solid_inertia_depth (0: the particle's own mass). Over the middle
 * third of a block six times as wide as deep, the water that moves with the floor is
 * less than rho0 H (the free sides let it go round): m_w is taken from the run with
 * depth 0 and must lie within 80-100 % of rho0 H; with it the run with 4 dx must give
 * the free plate's load of 4 times the mass within 1 % (the load changes by a factor of
 * 2.3, so a key that is not read, or scales the wrong thing, misses by far more), and
 * half a spacing must change nothing (the mass is never below the particle's own). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "isph_ppe.h"

#include "unit_check.h"
#include "unit_isph_operators.h"

#define NX 60
#define NY 10
#define DX 0.01
#define RHO0 1000.0
#define RHO_S 2700.0
#define G 9.81

/* The load per unit length on the floor's middle third after one projection with
 * the given solid_inertia_depth; -1 when a step fails. */
static double floor_load(double depth)
{
    const int n = NX * NY + NX;
    fluid_particles p;
    if (fluid_particles_alloc(&p, n, DX) != 0)
        return -1.0;
    for (int k = 0; k < n; k++) {
        const int i = k % NX, j = k / NX;   /* row NY is the floor, below the water */
        const int solid = j == NY;
        p.id[k] = k;
        p.flags[k] = solid ? FLUID_PARTICLE_MOVING_BOUNDARY : FLUID_PARTICLE_FLUID;
        p.x[k * 2] = (i + 0.5) * DX;
        p.x[k * 2 + 1] = solid ? -0.5 * DX : (j + 0.5) * DX;
        p.volume[k] = DX * DX;
        p.density[k] = RHO0;
        p.mass[k] = RHO0 * DX * DX;
        p.boundary_density[k] = solid ? RHO_S : 0.0;
    }
    unit_isph_operators o;
    double load = -1.0;
    const double dt = 1e-4, gravity[2] = {0.0, -G};
    double *u_star = calloc((size_t)n * 2, sizeof *u_star);
    double *zero = calloc((size_t)n * 2, sizeof *zero);
    double *force = calloc((size_t)n * 2, sizeof *force);
    const int built = unit_isph_operators_build(&o, &p);   /* o can be freed either way */
    if (!u_star || !zero || !force || built != 0)
        goto done;
    isph_geometry(&o.q, &p, &o.f);
    isph_free_surface(&o.q, &p, NULL, 1.4, 1.6, o.kernel.h, &o.f);
    isph_wall_velocity(&o.q, &p, NULL, &o.f);
    for (int k = 0; k < n; k++)
        if (p.flags[k] & FLUID_PARTICLE_FLUID)
            u_star[k * 2 + 1] = dt * gravity[1];    /* at rest, one step of gravity */
    isph_ppe ppe;
    isph_ppe_init(&ppe, (fsi_krylov_settings){1e-12, 2000}, FSI_PRECOND_ILU0, 0, 0.5 * DX);
    ppe.last_load = zero;       /* the solid's inertia in the equation, no earlier load */
    ppe.inertia_depth = depth;
    fsi_krylov_result res;
    char msg[256];
    const int rc =
        isph_ppe_solve(&ppe, &o.q, &p, &o.f, u_star, dt, RHO0, gravity, &res, msg, sizeof msg);
    if (rc != 0) {
        fprintf(stderr, "depth %g: %s\n", depth, msg);
        isph_ppe_free(&ppe);
        goto done;
    }
    isph_ppe_free(&ppe);
    isph_pressure_loads(&o.q, &p, NULL, force);
    double sum = 0.0;
    int count = 0;
    for (int k = NX * NY; k < n; k++) {
        const int i = k % NX;
        if (i >= NX / 3 && i < 2 * NX / 3) {
            sum += force[k * 2 + 1];
            count++;
        }
    }
    load = -sum / (count * DX);   /* the water pushes the floor down */
done:
    free(u_star);
    free(zero);
    free(force);
    unit_isph_operators_free(&o);
    fluid_particles_free(&p);
    return load;
}

int main(void)
{
#if FSI_DIM == 2
    const double column = RHO0 * NY * DX;    /* rho0 H */
    const double m0 = RHO_S * DX, m4 = 4.0 * m0;
    const double f0 = floor_load(0.0), f_half = floor_load(0.5 * DX), f4 = floor_load(4.0 * DX);
    /* 1 / F = 1 / (g M) + 1 / (g m_w) */
    const double water = 1.0 / (G / f0 - 1.0 / m0);
    const double expected = G * water * m4 / (water + m4);
    printf("load on the free floor: depth 0 %.3f N/m^2 (a free plate of %.0f kg/m^2 under "
           "%.1f kg/m^2 of water, of the block's %.0f); depth 0.5 dx %.3f; depth 4 dx %.3f, "
           "a free plate of %.0f kg/m^2 under the same water %.3f (hydrostatic %.1f)\n", f0,
           m0, water, column, f_half, f4, m4, expected, column * G);
    CHECK(f0 > 0.0 && water > 0.8 * column && water <= column, "depth 0: load %.4g, the "
          "water moving with the floor %.4g kg/m^2 of %.4g", f0, water, column);
    CHECK(f_half == f0, "depth 0.5 dx changed the load: %.6g against %.6g", f_half, f0);
    CHECK(fabs(f4 - expected) < 0.01 * expected, "depth 4 dx: load %.4g, a free plate of "
          "%g kg/m^2 carries %.4g", f4, m4, expected);
#endif
    return unit_check_report("test_isph_solid_inertia");
}
