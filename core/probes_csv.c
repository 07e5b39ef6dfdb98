#include "probes_csv.h"

#include "log.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* Appends one complete line, or nothing: a partial write is truncated away. */
static int write_line(fsi_probes_csv *csv, const char *line, size_t len)
{
    int err = 0;
    size_t done = fsi_write_all(csv->fd, line, len, &err);
    if (done < len) {
        snprintf(csv->error, sizeof csv->error, "cannot write %s: %s", csv->path,
                 strerror(err));
        if (done > 0 && ftruncate(csv->fd, csv->committed) == 0)
            lseek(csv->fd, csv->committed, SEEK_SET);
        return -1;
    }
    csv->committed += (off_t)len;
    return 0;
}

/* Grows *buf to hold at least need bytes. */
static int reserve(char **buf, size_t *cap, size_t need)
{
    if (need <= *cap)
        return 0;
    char *p = realloc(*buf, need);
    if (!p)
        return -1;
    *buf = p;
    *cap = need;
    return 0;
}

/* The length of a column's name without its unit: "tip_ux [m]" is the name "tip_ux"
 * and the unit "m" (*unit, *unit_len; "?" when the column gives none). */
static size_t split_unit(const char *column, const char **unit, size_t *unit_len)
{
    size_t len = strlen(column);
    const char *open = strstr(column, " [");
    if (len > 3 && column[len - 1] == ']' && open && open > column) {
        *unit = open + 2;
        *unit_len = (size_t)(column + len - 1 - *unit);
        return (size_t)(open - column);
    }
    *unit = "?";
    *unit_len = 1;
    return len;
}

int fsi_probes_csv_open(fsi_probes_csv *csv, const char *dir, const char *file, int n_columns,
                        char *const *column_names)
{
    csv->n_columns = n_columns;
    csv->committed = 0;
    csv->error[0] = '\0';
    snprintf(csv->path, sizeof csv->path, "%s/%s", dir, file);
    csv->fd = open(csv->path, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (csv->fd < 0) {
        snprintf(csv->error, sizeof csv->error, "cannot create %s: %s", csv->path,
                 strerror(errno));
        return -1;
    }
    /* Both lines together are at most twice the names' length plus the prefixes. */
    size_t len = 32, cap = 0;
    int units = 0;
    for (int i = 0; i < n_columns; i++) {
        const char *unit;
        size_t unit_len;
        len += 2 * strlen(column_names[i]) + 4;
        split_unit(column_names[i], &unit, &unit_len);
        units |= unit[0] != '?' || unit_len != 1;
    }
    char *line = NULL;
    if (reserve(&line, &cap, len) != 0) {
        snprintf(csv->error, sizeof csv->error, "out of memory for the header of %s",
                 csv->path);
        return -1;
    }
    size_t at = (size_t)snprintf(line, cap, "time");
    for (int i = 0; i < n_columns; i++) {
        const char *unit;
        size_t unit_len;
        const size_t name_len = split_unit(column_names[i], &unit, &unit_len);
        at += (size_t)snprintf(line + at, cap - at, ",%.*s", (int)name_len, column_names[i]);
    }
    at += (size_t)snprintf(line + at, cap - at, "\n");
    /* A comment line: readers that skip '#' lines (numpy, pandas with comment='#',
     * gnuplot) read the file as before, and the header stays the first line. */
    if (units) {
        at += (size_t)snprintf(line + at, cap - at, "# units: s");
        for (int i = 0; i < n_columns; i++) {
            const char *unit;
            size_t unit_len;
            split_unit(column_names[i], &unit, &unit_len);
            at += (size_t)snprintf(line + at, cap - at, ",%.*s", (int)unit_len, unit);
        }
        at += (size_t)snprintf(line + at, cap - at, "\n");
    }
    int rc = write_line(csv, line, at);
    free(line);
    return rc;
}

int fsi_probes_csv_resume(fsi_probes_csv *csv, const char *dir, const char *file,
                          int n_columns, off_t committed)
{
    csv->n_columns = n_columns;
    csv->committed = committed;
    csv->error[0] = '\0';
    snprintf(csv->path, sizeof csv->path, "%s/%s", dir, file);
    csv->fd = open(csv->path, O_WRONLY | O_CLOEXEC);
    struct stat st;
    if (csv->fd < 0 || fstat(csv->fd, &st) != 0) {
        snprintf(csv->error, sizeof csv->error, "cannot reopen %s: %s", csv->path,
                 strerror(errno));
        return -1;
    }
    if (st.st_size < committed) {
        snprintf(csv->error, sizeof csv->error, "%s holds %lld bytes, fewer than the %lld the "
                 "checkpoint counted: it is not this run's", csv->path, (long long)st.st_size,
                 (long long)committed);
        return -1;
    }
    if (ftruncate(csv->fd, committed) != 0 || lseek(csv->fd, committed, SEEK_SET) < 0) {
        snprintf(csv->error, sizeof csv->error, "cannot cut %s back to the checkpoint: %s",
                 csv->path, strerror(errno));
        return -1;
    }
    return 0;
}

int fsi_probes_csv_row(fsi_probes_csv *csv, double time, const double *values)
{
    if (csv->fd < 0)
        return 0;
    enum { NUMBER = 32 }; /* ",%.17g" of any double, with room to spare */
    size_t cap = (size_t)(csv->n_columns + 1) * NUMBER + 2;
    char *line = malloc(cap);
    if (!line) {
        snprintf(csv->error, sizeof csv->error, "out of memory for a row of %s", csv->path);
        return -1;
    }
    size_t at = (size_t)snprintf(line, cap, "%.17g", time);
    for (int i = 0; i < csv->n_columns; i++)
        at += (size_t)snprintf(line + at, cap - at, ",%.17g", values[i]);
    at += (size_t)snprintf(line + at, cap - at, "\n");
    int rc = write_line(csv, line, at);
    free(line);
    return rc;
}

int fsi_probes_csv_close(fsi_probes_csv *csv)
{
    int rc = 0;
    if (csv->fd >= 0 && close(csv->fd) != 0) {
        snprintf(csv->error, sizeof csv->error, "cannot close %s: %s", csv->path,
                 strerror(errno));
        rc = -1;
    }
    csv->fd = -1;
    return rc;
}
