/* How a solid point is named in a model's error message: "point id N at (x, y)
 * (reference (X, Y))", the "where" of solid_model.h's error convention. */
#ifndef FSI_SOLID_POINT_TEXT_H
#define FSI_SOLID_POINT_TEXT_H

#include <stddef.h>

#include "solid_particles.h"

void solid_describe_point(const solid_particles *p, int i, char *buf, size_t size);

#endif
