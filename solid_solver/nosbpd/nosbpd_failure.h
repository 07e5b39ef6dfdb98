/* Bond failure (000 §2.2.2): a bond whose stretch s = (|xi + eta| - |xi|) / |xi|
 * exceeds the critical stretch s0 breaks for ever (Eq. 47); the damage of a point
 * is the volume-weighted fraction of its broken bonds (Eq. 49).
 *
 * s0 is given directly (key critical_stretch) or follows from the energy release
 * rate G0 (key fracture_energy) by equating the work to break every bond across a
 * unit crack area with G0 (Silling & Askari 2005 in 3D; Ha & Bobaru 2010 in 2D):
 *   3D                 s0 = sqrt(5 G0 / (9 K delta))          (000 Eq. 48)
 *   2D plane stress    s0 = sqrt(4 pi G0 / (9 E delta))
 *   2D plane strain    s0 = sqrt(5 pi G0 / (12 E delta))
 * (the 2D forms are those of the bond-based material with the same E, the usual
 * practice for correspondence models). */
#ifndef NOSBPD_FAILURE_H
#define NOSBPD_FAILURE_H

#include "material.h"

/* s0 from the energy release rate G0 [J/m^2] for this material and horizon delta. */
double nosbpd_critical_stretch_from_energy(const material *mat, double fracture_energy,
                                           double delta);

#endif
