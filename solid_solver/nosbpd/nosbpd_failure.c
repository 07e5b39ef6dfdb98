/* Critical stretch from the energy release rate: see nosbpd_failure.h. */
#include "nosbpd_failure.h"

#include <math.h>

#include "dim.h"

double nosbpd_critical_stretch_from_energy(const material *mat, double fracture_energy,
                                           double delta)
{
    const double pi = 3.14159265358979323846;
#if FSI_DIM == 2
    const double e = mat->youngs_modulus;
    if (mat->plane == MATERIAL_PLANE_STRESS)
        return sqrt(4.0 * pi * fracture_energy / (9.0 * e * delta));
    return sqrt(5.0 * pi * fracture_energy / (12.0 * e * delta));
#else
    (void)pi;
    return sqrt(5.0 * fracture_energy / (9.0 * mat->bulk_modulus * delta)); /* 000 Eq. 48 */
#endif
}
