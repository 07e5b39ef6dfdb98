/* ISPH's free surface (fluid_solver/isph/isph_operators.h): on a block of fluid
 * particles on a square lattice, alone in space,
 *   - div r (uncorrected kernel, 003 §2.1) of a particle with a whole support is the
 *     lattice sum -sum dx^2 F(r) r^2 over the offsets within 2h, computed here apart
 *     (1.98159 for the cubic B-spline at h = 1.2 dx: 0.9 % under the dimension, the
 *     lattice quadrature), to round-off (1e-12), and B_a = (2 / div r) I (1e-12);
 *   - the top row (half a support: div r about 1.0) is free surface (p = 0 side of
 *     Skillen's blending, alpha = 0) with the outward normal (0, 1) (Eqs. 25-26,
 *     B_a corrected: 1e-6 away from the corners' reach), the row below it is near the
 *     surface with the same normal, and interior particles have alpha = 1;
 *   - alpha grows monotonically with div r between 1.4 and 1.6 (Eq. 17).
 * The bounds are those of a lattice: anything else (a sign, a missed pair, the wrong
 * kernel) misses them by orders of magnitude. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "small_tensor.h"

#include "unit_check.h"
#include "unit_isph_operators.h"

#define NX 24
#define NY 12
#define DX 0.01

int main(void)
{
#if FSI_DIM == 2
    fluid_particles p;
    if (fluid_particles_alloc(&p, NX * NY, DX) != 0)
        return 2;
    for (int j = 0; j < NY; j++)
        for (int i = 0; i < NX; i++) {
            const int k = j * NX + i;
            p.id[k] = k;
            p.flags[k] = FLUID_PARTICLE_FLUID;
            p.x[k * 2] = (i + 0.5) * DX;
            p.x[k * 2 + 1] = (j + 0.5) * DX;
            p.volume[k] = DX * DX;
            p.density[k] = 1000.0;
            p.mass[k] = 1000.0 * DX * DX;
        }
    unit_isph_operators o;
    CHECK(unit_isph_operators_build(&o, &p) == 0, "neighbour lists, pairs and fields");
    const cubic_spline_kernel *kernel = &o.kernel;
    const isph_fields *f = &o.f;
    isph_geometry(&o.q, &p, &o.f);
    isph_free_surface(&o.q, &p, NULL, 1.4, 1.6, kernel->h, &o.f);

    /* the lattice sum, apart from the scheme's pairs */
    double lattice = 0.0;
    for (int a = -3; a <= 3; a++)
        for (int b = -3; b <= 3; b++) {
            double w, fr;
            const double r2 = (a * a + b * b) * DX * DX;
            cubic_spline_eval2(kernel, r2, &w, &fr);
            lattice -= DX * DX * fr * r2;
        }
    double worst_div = 0.0, worst_b = 0.0, worst_top = 0.0, worst_alpha_inside = 0.0;
    int top_surface = 1, second_near = 1, monotone = 1;
    for (int j = 0; j < NY; j++)
        for (int i = 0; i < NX; i++) {
            const int k = j * NX + i;
            const int inside = i >= 3 && i < NX - 3 && j >= 3 && j < NY - 3;
            if (inside) {
                worst_div = fmax(worst_div, fabs(f->div_r[k] - lattice) / lattice);
                double id[FSI_MAT_SIZE];
                fsi_mat_identity(id);
                for (int m = 0; m < FSI_MAT_SIZE; m++)
                    worst_b = fmax(worst_b, fabs(f->b[k * FSI_MAT_SIZE + m] -
                                                 2.0 / lattice * id[m]));
                worst_alpha_inside = fmax(worst_alpha_inside, fabs(f->alpha[k] - 1.0));
            }
            const int away_from_sides = i >= 3 && i < NX - 3;
            if (j == NY - 1 && away_from_sides) {
                top_surface &= f->where[k] == ISPH_SURFACE && f->alpha[k] == 0.0;
                worst_top = fmax(worst_top, fabs(f->normal[k * 2]) + fabs(f->normal[k * 2 + 1] - 1.0));
            }
            if (j == NY - 2 && away_from_sides)
                second_near &= f->where[k] == ISPH_NEAR_SURFACE &&
                               fabs(f->normal[k * 2 + 1] - 1.0) < 1e-6;
            /* down a column, div r and alpha grow together */
            if (j > 0 && away_from_sides) {
                const int below = k - NX;
                if (f->div_r[below] > f->div_r[k] && f->alpha[below] < f->alpha[k])
                    monotone = 0;
            }
        }
    printf("lattice div r %.6f; interior: div r off it by %.3g, B off (2 / div r) I by %.3g, "
           "|alpha - 1| <= %.3g; top row: normal off (0, 1) by %.3g\n", lattice, worst_div,
           worst_b, worst_alpha_inside, worst_top);
    CHECK(worst_div < 1e-12, "div r inside the block is %.3g (relative) off the lattice sum",
          worst_div);
    CHECK(worst_b < 1e-12, "B_a inside the block is %.3g off (2 / div r) I", worst_b);
    CHECK(worst_alpha_inside == 0.0, "an interior particle has alpha != 1");
    CHECK(top_surface, "the top row is not all free surface with alpha = 0");
    CHECK(worst_top < 1e-6, "the top row's normal is %.3g away from (0, 1)", worst_top);
    CHECK(second_near, "the second row is not near-surface with the top row's normal");
    CHECK(monotone, "alpha does not grow with div r");
    unit_isph_operators_free(&o);
    fluid_particles_free(&p);
#endif
    return unit_check_report("test_isph_free_surface");
}
