#include "probes_csv.h"

#include <limits.h>

#include "log.h"

int fsi_probes_csv_open(fsi_probes_csv *csv, const char *dir, int n_columns,
                        char *const *column_names)
{
    char path[PATH_MAX];
    snprintf(path, sizeof path, "%s/probes.csv", dir);
    csv->file = fopen(path, "w");
    csv->n_columns = n_columns;
    if (!csv->file) {
        fsi_error("cannot create %s", path);
        return -1;
    }
    fprintf(csv->file, "time");
    for (int i = 0; i < n_columns; i++)
        fprintf(csv->file, ",%s", column_names[i]);
    fprintf(csv->file, "\n");
    fflush(csv->file);
    return 0;
}

void fsi_probes_csv_row(fsi_probes_csv *csv, double time, const double *values)
{
    if (!csv->file)
        return;
    fprintf(csv->file, "%.17g", time);
    for (int i = 0; i < csv->n_columns; i++)
        fprintf(csv->file, ",%.17g", values[i]);
    fprintf(csv->file, "\n");
    fflush(csv->file);
}

void fsi_probes_csv_close(fsi_probes_csv *csv)
{
    if (csv->file)
        fclose(csv->file);
    csv->file = NULL;
}
