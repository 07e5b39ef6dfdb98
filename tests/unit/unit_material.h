/* A material made by hand for the material tests (no case file): the kind, the 2D
 * idealisation, E and nu, density 1000 kg/m^3, no Drucker-Prager strength, and the
 * constants material_derive() derives. Header-only: every test is one executable. */
#ifndef FSI_UNIT_MATERIAL_H
#define FSI_UNIT_MATERIAL_H

#include <string.h>

#include "material.h"

static inline material unit_material(material_kind kind, material_plane plane, double E,
                                     double nu)
{
    material m;
    memset(&m, 0, sizeof m);
    m.kind = kind;
    m.plane = plane;
    m.density = 1000.0;
    m.youngs_modulus = E;
    m.poisson_ratio = nu;
    material_derive(&m);
    return m;
}

#endif
