/* Constants of the Silling 2017 zero-energy mode control: see nosbpd_stabilisation.h. */
#include "nosbpd_stabilisation.h"

#include <math.h>

#include "dim.h"

double nosbpd_micromodulus(const material *mat, double delta)
{
    const double pi = 3.14159265358979323846;
    const double m = material_wave_modulus(mat), mu = mat->shear_modulus;
#if FSI_DIM == 2
    return 12.0 * (m - mu) / (pi * delta * delta * delta);
#else
    return 18.0 * (m - 4.0 * mu / 3.0) / (pi * delta * delta * delta * delta);
#endif
}

double nosbpd_stabilisation_modulus(const material *mat, double coefficient, double delta,
                                    const nosbpd_full_family *full)
{
    if (coefficient == 0.0 || full->sum_weight <= 0.0)
        return 0.0;
    return coefficient * nosbpd_micromodulus(mat, delta) * full->sum_volume_over_length /
           full->sum_weight;
}
