#include "state_file.h"

#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "dim.h"
#include "log.h"

#define MAGIC "fsi-state 1\n"

/* FNV-1a over every byte after the header line: cheap, and any cut or flipped byte
 * changes it. */
static uint64_t fnv1a(uint64_t h, const void *data, size_t n)
{
    const unsigned char *b = data;
    for (size_t i = 0; i < n; i++) {
        h ^= b[i];
        h *= 1099511628211ull;
    }
    return h;
}

typedef struct {
    FILE *f;
    uint64_t sum;
    int failed;
} sink;

static void put(sink *s, const void *data, size_t n)
{
    if (n > 0 && fwrite(data, 1, n, s->f) != n)
        s->failed = 1;
    s->sum = fnv1a(s->sum, data, n);
}

int fsi_state_write_file(const fsi_state *st, const char *path, char *msg, size_t msg_size)
{
    char tmp[4200];
    snprintf(tmp, sizeof tmp, "%s.tmp", path);
    sink s = {fopen(tmp, "wb"), 14695981039346656037ull, 0};
    if (!s.f) {
        snprintf(msg, msg_size, "cannot create %s: %s", tmp, strerror(errno));
        return -1;
    }
    fputs(MAGIC, s.f);
    char version[128] = "";
    snprintf(version, sizeof version, "%s", FSI_VERSION);
    const int32_t dim = FSI_DIM;
    int32_t n = 0;
    for (int i = 0; i < st->n; i++)
        n += st->entry[i].used;
    put(&s, version, sizeof version);
    put(&s, &dim, sizeof dim);
    put(&s, &n, sizeof n);
    for (int i = 0; i < st->n; i++) {
        const fsi_state_entry *e = &st->entry[i];
        if (!e->used)
            continue;
        const uint64_t bytes = e->bytes;
        put(&s, e->name, sizeof e->name);
        put(&s, &bytes, sizeof bytes);
        put(&s, e->data, e->bytes);
    }
    const uint64_t sum = s.sum;
    if (fwrite(&sum, sizeof sum, 1, s.f) != 1)
        s.failed = 1;
    int err = s.failed ? (errno ? errno : EIO) : 0;
    if (fflush(s.f) != 0 && !err)
        err = errno;
    if (fclose(s.f) != 0 && !err)
        err = errno;
    if (!err && rename(tmp, path) != 0)
        err = errno;
    if (err) {
        snprintf(msg, msg_size, "cannot write %s: %s", path, strerror(err));
        remove(tmp);
        return -1;
    }
    return 0;
}

static int get(FILE *f, void *data, size_t n, uint64_t *sum)
{
    if (n > 0 && fread(data, 1, n, f) != n)
        return -1;
    *sum = fnv1a(*sum, data, n);
    return 0;
}

int fsi_state_read_file(fsi_state *st, const char *path, char *msg, size_t msg_size)
{
    fsi_state_clear(st);
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(msg, msg_size, "cannot open %s: %s", path, strerror(errno));
        return -1;
    }
    char magic[sizeof MAGIC] = "", version[128];
    int32_t dim, n;
    uint64_t sum = 14695981039346656037ull, stored;
    const char *why = NULL;
    void *buf = NULL;
    if (fread(magic, 1, sizeof MAGIC - 1, f) != sizeof MAGIC - 1 || strcmp(magic, MAGIC) != 0)
        why = "not a saved state";
    else if (get(f, version, sizeof version, &sum) || get(f, &dim, sizeof dim, &sum) ||
             get(f, &n, sizeof n, &sum))
        why = "truncated";
    else if (version[sizeof version - 1] != '\0' || strcmp(version, FSI_VERSION) != 0) {
        version[sizeof version - 1] = '\0';
        snprintf(msg, msg_size, "%s was written by version %s of the code, this is %s: a "
                 "checkpoint restarts only the build that wrote it", path, version,
                 FSI_VERSION);
        fclose(f);
        return -1;
    } else if (dim != FSI_DIM)
        why = "written by a build of another dimension (FSI_DIM)";
    for (int32_t i = 0; !why && i < n; i++) {
        char name[sizeof st->entry[0].name];
        uint64_t bytes;
        if (get(f, name, sizeof name, &sum) || get(f, &bytes, sizeof bytes, &sum) ||
            name[sizeof name - 1] != '\0') {
            why = "truncated or corrupt";
            break;
        }
        void *grown = realloc(buf, bytes > 0 ? (size_t)bytes : 1);
        if (!grown) {
            why = "too large for memory (corrupt?)";
            break;
        }
        buf = grown;
        if (get(f, buf, (size_t)bytes, &sum)) {
            why = "truncated";
            break;
        }
        if (fsi_state_put(st, name, buf, (size_t)bytes) != 0)
            why = "too large for memory";
    }
    if (!why && (fread(&stored, sizeof stored, 1, f) != 1 || stored != sum))
        why = "corrupt (its checksum does not match: cut short or changed)";
    if (!why && fgetc(f) != EOF)
        why = "corrupt (bytes after its end)";
    free(buf);
    fclose(f);
    if (why) {
        snprintf(msg, msg_size, "%s: %s", path, why);
        fsi_state_clear(st);
        return -1;
    }
    return 0;
}
