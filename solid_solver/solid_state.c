/* A solid's state as named arrays (solid_state.h). */
#include "solid_state.h"

int solid_state_put_fields(fsi_state *st, const solid_state_field *f, int count)
{
    for (int k = 0; k < count; k++)
        if (fsi_state_put(st, f[k].name, f[k].data, f[k].bytes) != 0)
            return -1;
    return 0;
}

int solid_state_fields_match(const fsi_state *st, const solid_state_field *f, int count)
{
    for (int k = 0; k < count; k++)
        if (fsi_state_size(st, f[k].name) != f[k].bytes)
            return 0;
    return 1;
}

int solid_state_get_fields(const fsi_state *st, const solid_state_field *f, int count)
{
    if (!solid_state_fields_match(st, f, count))
        return -1;
    for (int k = 0; k < count; k++)
        if (fsi_state_get(st, f[k].name, f[k].data, f[k].bytes) != 0)
            return -1;      /* not reached: the sizes matched */
    return 0;
}
