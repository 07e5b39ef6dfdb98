/* Named state of the fluid's parts in a core/state_store.h container: what the main
 * loop and the schemes save at a coupling window's start and restore when the window
 * is repeated (fluid_scheme_save_state, fluid_main.c). Every part puts its entries
 * under "<prefix>.<field>" (the prefix names the part, e.g. "ulph.list"), so that two
 * parts never share a name. */
#ifndef FSI_FLUID_STATE_H
#define FSI_FLUID_STATE_H

#include <stdio.h>

#include "state_store.h"

/* "<prefix>.<field>" into name[64] (the store's longest name). */
static inline const char *fluid_state_name(char name[64], const char *prefix, const char *field)
{
    snprintf(name, 64, "%s.%s", prefix, field);
    return name;
}

/* fsi_state_put under "<prefix>.<field>". */
static inline int fluid_state_put(fsi_state *st, const char *prefix, const char *field,
                                  const void *data, size_t bytes)
{
    char name[64];
    return fsi_state_put(st, fluid_state_name(name, prefix, field), data, bytes);
}

/* fsi_state_get under "<prefix>.<field>": exactly bytes, or -1. */
static inline int fluid_state_get(const fsi_state *st, const char *prefix, const char *field,
                                  void *data, size_t bytes)
{
    char name[64];
    return fsi_state_get(st, fluid_state_name(name, prefix, field), data, bytes);
}

/* The size of "<prefix>.<field>", or (size_t)-1 when there is none. */
static inline size_t fluid_state_size(const fsi_state *st, const char *prefix, const char *field)
{
    char name[64];
    return fsi_state_size(st, fluid_state_name(name, prefix, field));
}

#endif
