/* probes.csv: one header line "time,<probe>_<quantity>,..." and one row per probe
 * time, flushed row by row so a stopped run leaves a readable file. */
#ifndef FSI_PROBES_CSV_H
#define FSI_PROBES_CSV_H

#include <stdio.h>

typedef struct {
    FILE *file;
    int n_columns;
} fsi_probes_csv;

/* Opens DIR/probes.csv and writes the header; returns 0 or -1. */
int fsi_probes_csv_open(fsi_probes_csv *csv, const char *dir, int n_columns,
                        char *const *column_names);
/* values[n_columns], printed exactly (%.17g) so runs compare bit for bit. */
void fsi_probes_csv_row(fsi_probes_csv *csv, double time, const double *values);
void fsi_probes_csv_close(fsi_probes_csv *csv);

#endif
