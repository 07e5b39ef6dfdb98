#include "state_store.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static fsi_state_entry *find(const fsi_state *st, const char *name)
{
    for (int i = 0; i < st->n; i++)
        if (st->entry[i].used && strcmp(st->entry[i].name, name) == 0)
            return &st->entry[i];
    return NULL;
}

void fsi_state_clear(fsi_state *st)
{
    for (int i = 0; i < st->n; i++)
        st->entry[i].used = 0;
    st->failed = 0;
}

/* An unused entry, the one that last held name when there is one (its memory fits),
 * else any unused one, else a new one. */
static fsi_state_entry *free_entry(fsi_state *st, const char *name)
{
    fsi_state_entry *spare = NULL;
    for (int i = 0; i < st->n; i++) {
        if (st->entry[i].used)
            continue;
        if (strcmp(st->entry[i].name, name) == 0)
            return &st->entry[i];
        if (!spare)
            spare = &st->entry[i];
    }
    if (spare)
        return spare;
    if (st->n == st->capacity) {
        int cap = st->capacity ? 2 * st->capacity : 32;
        fsi_state_entry *grown = realloc(st->entry, (size_t)cap * sizeof *grown);
        if (!grown)
            return NULL;
        memset(grown + st->n, 0, (size_t)(cap - st->n) * sizeof *grown);
        st->entry = grown;
        st->capacity = cap;
    }
    return &st->entry[st->n++];
}

int fsi_state_put(fsi_state *st, const char *name, const void *data, size_t bytes)
{
    fsi_state_entry *e = find(st, name);
    if (!e)
        e = free_entry(st, name);
    if (!e) {
        st->failed = 1;
        return -1;
    }
    if (bytes > e->capacity || !e->data) {
        void *grown = realloc(e->data, bytes > 0 ? bytes : 1);
        if (!grown) {
            st->failed = 1;
            return -1;
        }
        e->data = grown;
        e->capacity = bytes;
    }
    if (bytes > 0)
        memcpy(e->data, data, bytes);
    snprintf(e->name, sizeof e->name, "%s", name);
    e->bytes = bytes;
    e->used = 1;
    return 0;
}

size_t fsi_state_size(const fsi_state *st, const char *name)
{
    const fsi_state_entry *e = find(st, name);
    return e ? e->bytes : (size_t)-1;
}

int fsi_state_get(const fsi_state *st, const char *name, void *data, size_t bytes)
{
    const fsi_state_entry *e = find(st, name);
    if (!e || e->bytes != bytes)
        return -1;
    if (bytes > 0)
        memcpy(data, e->data, bytes);
    return 0;
}

const void *fsi_state_data(const fsi_state *st, const char *name, size_t *bytes)
{
    const fsi_state_entry *e = find(st, name);
    if (!e)
        return NULL;
    if (bytes)
        *bytes = e->bytes;
    return e->data;
}

int fsi_state_put_fields(fsi_state *st, const fsi_state_field *f, int count)
{
    for (int k = 0; k < count; k++)
        if (fsi_state_put(st, f[k].name, f[k].data, f[k].bytes) != 0)
            return -1;
    return 0;
}

int fsi_state_fields_match(const fsi_state *st, const fsi_state_field *f, int count)
{
    for (int k = 0; k < count; k++)
        if (fsi_state_size(st, f[k].name) != f[k].bytes)
            return 0;
    return 1;
}

int fsi_state_get_fields(const fsi_state *st, const fsi_state_field *f, int count)
{
    if (!fsi_state_fields_match(st, f, count))
        return -1;
    for (int k = 0; k < count; k++)
        if (fsi_state_get(st, f[k].name, f[k].data, f[k].bytes) != 0)
            return -1;      /* not reached: the sizes matched */
    return 0;
}

void fsi_state_free(fsi_state *st)
{
    for (int i = 0; i < st->n; i++)
        free(st->entry[i].data);
    free(st->entry);
    *st = (fsi_state){0};
}
