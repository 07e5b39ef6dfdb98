/* Private to materials/: the per-model updates behind material_update(). */
#ifndef FSI_MATERIAL_MODELS_H
#define FSI_MATERIAL_MODELS_H

#include "material.h"

/* linear_elastic.c: 000 Eq. 43 with Hooke's D; plane stress solves deps[2]. */
void material_linear_elastic_update(const material *m, double deps[6], double stress[6],
                                    material_state *st);

/* drucker_prager.c: elastic predictor, closed-form return to the cone or its apex. */
void material_drucker_prager_update(const material *m, double deps[6], double stress[6],
                                    material_state *st);

#endif
