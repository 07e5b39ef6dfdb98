/* A time series as CSV (probes.csv, coupling.csv): one header line
 * "time,<column>,...", when a column names its unit a second line
 * "# units: s,<unit>,..." (docs/output.md), and one row per time. Each row reaches the file with one write(); a failed or short write (disk
 * full) is cut back to the last complete row, so the file always ends at a row. */
#ifndef FSI_PROBES_CSV_H
#define FSI_PROBES_CSV_H

#include <sys/types.h>

typedef struct {
    int fd;            /* -1 when closed */
    int n_columns;
    off_t committed;   /* bytes of complete lines */
    char path[4096];
    char error[4400];  /* the last failure: file and system error text */
} fsi_probes_csv;

/* Opens DIR/FILE and writes the header; returns 0 or -1 (message in error). A column
 * name may end in its unit in brackets, "tip_ux [m]" (what fsi_add_probe was given):
 * the header then holds the bare name and the units line the unit ("?" for a column
 * without one). */
int fsi_probes_csv_open(fsi_probes_csv *csv, const char *dir, const char *file, int n_columns,
                        char *const *column_names);
/* Reopens DIR/FILE of a restarted run (docs/checkpoints.md): cut back to its first
 * 'committed' bytes, the complete rows of the run up to the checkpoint, and written
 * on from there. 0, or -1 (message in error; also when the file is shorter). */
int fsi_probes_csv_resume(fsi_probes_csv *csv, const char *dir, const char *file,
                          int n_columns, off_t committed);
/* values[n_columns], printed exactly (%.17g) so runs compare bit for bit. Returns 0,
 * or -1 with csv->error set when the row could not be written (the file then still
 * ends at the previous row). */
int fsi_probes_csv_row(fsi_probes_csv *csv, double time, const double *values);
/* Returns 0, or -1 with csv->error set when closing reported a failed write. */
int fsi_probes_csv_close(fsi_probes_csv *csv);

#endif
