/* The case check of the solid's sub-step (solid_keys.h): time_step_safety times the
 * lattice bound dx / sqrt(M / rho) of the material (material_wave_crossing_time, the
 * bound the running model also takes, nosbpd_model.c). The model's step is never
 * longer than that bound, so a case refused here would take at least the number of
 * sub-steps the message names. */
#include "case_check.h"
#include "material.h"
#include "solid_keys.h"

int solid_step_check(const fsi_case *c, const char *role, FILE *errors)
{
    fsi_case_checker k = {c, errors, 0};
    material m;
    char msg[256];
    if (material_from_case(&m, c, role, msg, sizeof msg) != 0)
        return 0;   /* material_case_check reports it */
    const double dx = fsi_case_get_real(c, role, "spacing", 0.0);
    const double safety = fsi_case_get_real(c, role, "time_step_safety", 0.8);
    const double step = safety * material_wave_crossing_time(&m, m.density, dx);
    /* References: a steel-stiff solid of water's density at millimetre spacing. */
    const fsi_step_factor f[] = {{role, "time_step_safety", safety, 0.8, 1.0},
                                 {role, "spacing", dx, 1e-3, 1.0},
                                 {role, "density", m.density, 1000.0, 0.5},
                                 {role, "youngs_modulus", m.youngs_modulus, 2.1e11, -0.5}};
    char what[256];
    snprintf(what, sizeof what, "the solid's sub-step time_step_safety dx / sqrt(M / rho) = "
             "%g * %g m / sqrt(%g Pa / %g kg/m^3)", safety, dx, material_wave_modulus(&m),
             m.density);
    fsi_case_check_step(&k, step, what, f, (int)(sizeof f / sizeof f[0]));
    return k.errors;
}
