/* ISPH's operators on a set of particles, for the ISPH unit tests: the cubic B-spline
 * at h = 1.2 dx (ISPH_H_OVER_DX), the neighbour lists, the pairs and the fields with
 * the corrected gradient (B_a), built once. unit_isph_operators_free releases them. */
#ifndef FSI_UNIT_ISPH_OPERATORS_H
#define FSI_UNIT_ISPH_OPERATORS_H

#include "cubic_spline.h"
#include "isph_operators.h"
#include "isph_pairs.h"
#include "verlet_list.h"

typedef struct {
    cubic_spline_kernel kernel;
    fluid_verlet list;
    isph_pairs q;
    isph_fields f;
} unit_isph_operators;

/* 0, or -1 when a list, the pairs or the fields cannot be built. */
static inline int unit_isph_operators_build(unit_isph_operators *o, const fluid_particles *p)
{
    cubic_spline_init(&o->kernel, 1.2 * p->spacing);
    fluid_verlet_init(&o->list);
    isph_pairs_init(&o->q);
    isph_fields_init(&o->f);
    o->f.correct = 1;
    if (fluid_verlet_update(&o->list, p, o->kernel.support, 0.0) < 0 ||
        isph_pairs_build(&o->q, &o->list, &o->kernel, p) != 0 ||
        isph_fields_reserve(&o->f, p->n) != 0)
        return -1;
    return 0;
}

static inline void unit_isph_operators_free(unit_isph_operators *o)
{
    isph_fields_free(&o->f);
    isph_pairs_free(&o->q);
    fluid_verlet_free(&o->list);
}

#endif
