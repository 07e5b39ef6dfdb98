/* A solid's state as named arrays of an fsi_state (core/state_store.h), the form in
 * which the main loop (solid_main.c) and every model (solid_model_save_state,
 * solid_model_restore_state) save what a repeated coupling window must start from:
 * each lists its arrays once as fields and saves or restores them all.
 *
 *     solid_state_field f[] = {{"nosbpd.stress", m->stress, n * 6 * sizeof(double)}, ...};
 *     solid_state_put_fields(st, f, count);           // save
 *     solid_state_get_fields(st, f, count);           // restore: all or nothing
 *
 * Names are "<owner>.<array>" (owner: "solid" for the main loop, the model's name for
 * the model), so that the main loop's and the model's entries share one store. */
#ifndef FSI_SOLID_STATE_H
#define FSI_SOLID_STATE_H

#include <stddef.h>

#include "state_store.h"

typedef struct {
    const char *name;       /* "<owner>.<array>", below 64 characters */
    void *data;             /* the array itself (read by put, written by get) */
    size_t bytes;
} solid_state_field;

/* Copies every field into st (without clearing it). 0, or -1 when memory runs out. */
int solid_state_put_fields(fsi_state *st, const solid_state_field *f, int count);

/* 1 when st holds every field with exactly its size, else 0 (a state saved by another
 * configuration, or not at all). */
int solid_state_fields_match(const fsi_state *st, const solid_state_field *f, int count);

/* Copies every field back from st when all of them match (solid_state_fields_match):
 * 0; else -1, and nothing is changed. */
int solid_state_get_fields(const fsi_state *st, const solid_state_field *f, int count);

#endif
