/* Derived constants, the wave modulus, stress invariants and the dispatch of
 * material_update() to the model files (linear_elastic.c, drucker_prager.c; the
 * hyperelastic kinds have only the total form of hyperelastic.c). */
#include <math.h>

#include "dim.h"
#include "material_models.h"

/* The Drucker-Prager cone f = alpha I1 + sqrt(J2) - k matched to the Mohr-Coulomb
 * envelope tau = c - sigma_n tan(phi) (tension positive) in PLANE STRAIN
 * (Drucker & Prager 1952; de Souza Neto, Peric & Owen 2008, Sec. 6.4.2, the
 * "plane strain match"; the form used by Bui et al. 2008 for SPH soil models):
 *     alpha = tan(phi) / sqrt(9 + 12 tan^2 phi) = sin(phi) / sqrt(9 + 3 sin^2 phi)
 *     k     = 3 c / sqrt(9 + 12 tan^2 phi)    = 3 c cos(phi) / sqrt(9 + 3 sin^2 phi)
 * and the plastic potential g = beta I1 + sqrt(J2) with the same map from psi:
 *     beta  = sin(psi) / sqrt(9 + 3 sin^2 psi),
 * which gives exactly the Mohr-Coulomb plane-strain dilatancy (in-plane plastic
 * volume change / maximum plastic shear = sin psi). The sin/cos forms are used
 * because they stay finite for every angle. Why this match, and how far it is from
 * the exact non-associated limit-load match, is in docs/materials.md. */
void material_derive(material *m)
{
    double E = m->youngs_modulus, nu = m->poisson_ratio;
    m->shear_modulus = E / (2.0 * (1.0 + nu));
    m->bulk_modulus = E / (3.0 * (1.0 - 2.0 * nu));
    m->lame_lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));

    double sp = sin(m->friction_angle), cp = cos(m->friction_angle);
    double sd = sin(m->dilation_angle);
    double rp = sqrt(9.0 + 3.0 * sp * sp);
    m->dp_alpha = sp / rp;
    m->dp_k = 3.0 * m->cohesion * cp / rp;
    m->dp_beta = sd / sqrt(9.0 + 3.0 * sd * sd);
}

double material_wave_modulus(const material *m)
{
#if FSI_DIM == 2
    /* Plane stress: the in-plane P-wave modulus of a thin plate, the (1,1) entry of
     * the plane-stress Hooke matrix. */
    if (m->plane == MATERIAL_PLANE_STRESS)
        return m->youngs_modulus / (1.0 - m->poisson_ratio * m->poisson_ratio);
#endif
    return m->lame_lambda + 2.0 * m->shear_modulus;
}

double material_wave_crossing_time(const material *m, double density, double dx)
{
    return dx / sqrt(material_wave_modulus(m) / density);
}

double material_i1(const double s[6])
{
    return s[0] + s[1] + s[2];
}

double material_j2(const double s[6])
{
    /* J2 = ((s11-s22)^2 + (s22-s33)^2 + (s33-s11)^2) / 6 + s12^2 + s23^2 + s31^2: the
     * difference form needs no mean stress, so no cancellation under large pressure. */
    double a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
    return (a * a + b * b + c * c) / 6.0 + s[3] * s[3] + s[4] * s[4] + s[5] * s[5];
}

double material_dp_yield(const material *m, const double stress[6])
{
    return m->dp_alpha * material_i1(stress) + sqrt(material_j2(stress)) - m->dp_k;
}

void material_update(const material *m, double deps[6], double stress[6], material_state *st)
{
    switch (m->kind) {
    case MATERIAL_DRUCKER_PRAGER:
        material_drucker_prager_update(m, deps, stress, st);
        break;
    case MATERIAL_SAINT_VENANT_KIRCHHOFF:
    case MATERIAL_NEO_HOOKEAN:
        /* A stress of F alone has no rate form here; running Hooke's law instead
         * would be a different material under this one's name. NaN makes the
         * caller's finiteness check stop the run (material.h). */
        for (int i = 0; i < 6; i++)
            stress[i] = NAN;
        if (st)
            st->yielding = 0;
        break;
    case MATERIAL_LINEAR_ELASTIC:
    default:
        material_linear_elastic_update(m, deps, stress, st);
        break;
    }
}
