/* A solver's state between two instants, as named byte arrays: what a participant
 * saves at a coupling window's start and restores when the coupler repeats the
 * window (implicit coupling, docs/coupling.md), and what a coupled checkpoint writes
 * to disk. The solver decides what its state is; the store only keeps copies.
 *
 *     fsi_state_clear(st);                          // reuses the memory of last time
 *     fsi_state_put(st, "x", p->x, n * DIM * sizeof(double));
 *     fsi_state_put_value(st, "steps", &steps, sizeof steps);
 *     ...
 *     fsi_state_get(st, "x", p->x, n * DIM * sizeof(double));   // exact size, or -1
 *
 * Ownership: the store owns its copies; fsi_state_free releases them. */
#ifndef FSI_STATE_STORE_H
#define FSI_STATE_STORE_H

#include <stddef.h>

typedef struct {
    char name[64];
    size_t bytes, capacity;
    void *data;
    int used;
} fsi_state_entry;

typedef struct {
    int n, capacity;
    fsi_state_entry *entry;
    int failed;            /* a put ran out of memory since the last clear */
} fsi_state;

/* Marks every entry unused, keeping the memory for the next puts. */
void fsi_state_clear(fsi_state *st);

/* Copies bytes from data under name (replacing an entry of that name). A put that
 * runs out of memory sets st->failed and returns -1. */
int fsi_state_put(fsi_state *st, const char *name, const void *data, size_t bytes);

/* The size of name's entry, or (size_t)-1 when there is none. */
size_t fsi_state_size(const fsi_state *st, const char *name);

/* Copies name's entry into data, which holds bytes. -1 when there is no entry of that
 * name or its size differs (the state belongs to another configuration). */
int fsi_state_get(const fsi_state *st, const char *name, void *data, size_t bytes);

/* name's entry itself (read-only, valid until the next put or clear), or NULL. */
const void *fsi_state_data(const fsi_state *st, const char *name, size_t *bytes);

/* A solver's state listed once as a table of fields, saved and restored as a whole:
 *
 *     fsi_state_field f[] = {{"nosbpd.stress", m->stress, n * 6 * sizeof(double)}, ...};
 *     fsi_state_put_fields(st, f, count);          // save
 *     fsi_state_get_fields(st, f, count);          // restore: all or nothing */
typedef struct {
    const char *name;       /* "<owner>.<array>", below 64 characters */
    void *data;             /* the array itself (read by put, written by get) */
    size_t bytes;
} fsi_state_field;

/* Copies every field into st (without clearing it). 0, or -1 when memory runs out. */
int fsi_state_put_fields(fsi_state *st, const fsi_state_field *f, int count);

/* 1 when st holds every field with exactly its size, else 0 (a state saved by another
 * configuration, or not at all). */
int fsi_state_fields_match(const fsi_state *st, const fsi_state_field *f, int count);

/* Copies every field back from st when all of them match: 0; else -1, and nothing is
 * changed. */
int fsi_state_get_fields(const fsi_state *st, const fsi_state_field *f, int count);

void fsi_state_free(fsi_state *st);

#endif
