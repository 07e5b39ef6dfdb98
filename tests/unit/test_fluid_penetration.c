/* The fluid's penetration check (fluid_coupling_count_inside): a fluid particle is
 * inside the solid when it is closer to a solid particle than half that particle's own
 * spacing, V^(1/DIM) / 2. With a solid four times finer than the fluid, a fluid particle
 * 0.3 dx_f from a solid particle is outside (the old radius, half the fluid's spacing,
 * counted it), one 0.11 dx_f away is inside; with equal spacings both are inside. */
#include <math.h>
#include <stdio.h>

#include "fluid_coupling.h"
#include "fluid_scheme.h"
#include "unit_check.h"

/* fluid_coupling.c calls the scheme chosen at link time (fluid_scheme.h); the check
 * under test does not, but the static link needs the scheme's object pulled in before
 * the common library is scanned, which this reference does. */
void (*const fluid_penetration_test_scheme)(const fluid_scheme *, const fluid_particles *,
                                            double *) = fluid_scheme_boundary_loads;

static int count_with_solid_spacing(double solid_dx, int *first)
{
    const double dx = 0.01;
    fluid_particles p;
    fluid_particles_alloc(&p, 2, dx);
    const double at[2][2] = {{0.3 * dx, 0.0}, {0.1 * dx, 0.05 * dx}};
    for (int i = 0; i < 2; i++) {
        p.id[i] = i;
        p.flags[i] = FLUID_PARTICLE_FLUID;
        p.density[i] = 1000.0;
        p.mass[i] = 1000.0 * pow(dx, FSI_DIM);
        p.volume[i] = pow(dx, FSI_DIM);
        for (int d = 0; d < FSI_DIM; d++)
            p.x[i * FSI_DIM + d] = d < 2 ? at[i][d] : 0.0;
    }
    int32_t id = 0;
    double x[FSI_DIM] = {0}, v[FSI_DIM] = {0}, a[FSI_DIM] = {0};
    double volume = pow(solid_dx, FSI_DIM), density = 2700.0;
    fsi_interface solid = {.n = 1, .id = &id, .position = x, .velocity = v, .acceleration = a,
                           .volume = &volume, .density = &density};
    fluid_coupling c;
    fluid_coupling_init(&c, 2, 0.0);
    char msg[256];
    int count = -1;
    if (fluid_boundary_set(&c.boundary, &p, &solid, 1000.0, msg, sizeof msg) == 0)
        count = fluid_coupling_count_inside(&c, &p, first);
    else
        printf("fluid_boundary_set: %s\n", msg);
    fluid_coupling_free(&c);
    fluid_particles_free(&p);
    return count;
}

int main(void)
{
    int first = -2;
    const int finer = count_with_solid_spacing(0.0025, &first);
    printf("solid 4x finer: %d inside (first %d); ", finer, first);
    CHECK(finer == 1 && first == 1, "a solid 4x finer: %d inside, first %d (expected 1, 1)",
          finer, first);
    const int equal = count_with_solid_spacing(0.01, &first);
    printf("equal spacings: %d inside (first %d)\n", equal, first);
    CHECK(equal == 2 && first == 0, "equal spacings: %d inside, first %d (expected 2, 0)",
          equal, first);
    return unit_check_report("test_fluid_penetration");
}
