/* What every model's solid_model_create begins with, held once: the material of
 * [solid], the lattice spacing's check, and the allocation macro of its state. */
#ifndef FSI_SOLID_MODEL_SETUP_H
#define FSI_SOLID_MODEL_SETUP_H

#include <stddef.h>
#include <stdlib.h>

#include "case_file.h"
#include "material.h"
#include "solid_particles.h"

/* Clears msg, reads the [solid] material (material_from_case) into *mat and the
 * particles' spacing into *dx. Returns 0, or -1 with msg ("MODEL: ..." for the
 * spacing, the material's own message naming the key otherwise). */
int solid_model_setup(material *mat, double *dx, const fsi_case *c, const solid_particles *p,
                      const char *model, char *msg, size_t msg_size);

/* ptr = count zeroed elements (at least one), or goto out_of_memory: the create
 * functions free everything there. */
#define SOLID_ALLOC(ptr, count)                                                       \
    do {                                                                              \
        (ptr) = calloc((size_t)(count) > 0 ? (size_t)(count) : 1, sizeof *(ptr));     \
        if (!(ptr))                                                                   \
            goto out_of_memory;                                                       \
    } while (0)

#endif
