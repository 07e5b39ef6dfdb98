#include "diagnostics_csv.h"

#include <stdio.h>

int fsi_diagnostics_csv_open(fsi_diagnostics_csv *d, const char *dir, const char *participant,
                             int n_columns, char *const *names, off_t resume, char *msg,
                             size_t msg_size)
{
    char file[256];
    snprintf(file, sizeof file, "%s_diagnostics.csv", participant);
    const int rc = resume >= 0 ? fsi_probes_csv_resume(&d->csv, dir, file, n_columns, resume)
                               : fsi_probes_csv_open(&d->csv, dir, file, n_columns, names);
    if (rc != 0) {
        snprintf(msg, msg_size, "%s", d->csv.error);
        if (d->csv.fd >= 0)
            fsi_probes_csv_close(&d->csv);
        return -1;
    }
    d->open = 1;
    return 0;
}

int fsi_diagnostics_csv_row(fsi_diagnostics_csv *d, double t, const double *values, char *msg,
                            size_t msg_size)
{
    if (fsi_probes_csv_row(&d->csv, t, values) != 0) {
        snprintf(msg, msg_size, "%s", d->csv.error);
        return -1;
    }
    return 0;
}

off_t fsi_diagnostics_csv_bytes(const fsi_diagnostics_csv *d)
{
    return d->open ? d->csv.committed : 0;
}

void fsi_diagnostics_csv_close(fsi_diagnostics_csv *d)
{
    if (d->open)
        fsi_probes_csv_close(&d->csv);
    d->open = 0;
}
