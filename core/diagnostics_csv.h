/* A participant's diagnostics file, OUT/<participant>_diagnostics.csv (docs/output.md,
 * "Diagnostics over time"): a probes_csv.h time series that a participant creates at
 * its start or, at a restart, cuts back to the length its checkpoint kept. What the
 * columns hold is the participant's (fluid_solver/fluid_diagnostics.c,
 * solid_solver/solid_diagnostics.c). */
#ifndef FSI_DIAGNOSTICS_CSV_H
#define FSI_DIAGNOSTICS_CSV_H

#include <stddef.h>
#include <sys/types.h>

#include "probes_csv.h"

typedef struct {
    fsi_probes_csv csv;
    int open;               /* the file is open (a zeroed struct is closed) */
} fsi_diagnostics_csv;

/* Creates DIR/PARTICIPANT_diagnostics.csv with the header "time,<names>", or, with
 * resume >= 0 (a restarted run, docs/checkpoints.md), reopens it cut back to its first
 * 'resume' bytes. 0, or -1 with msg. */
int fsi_diagnostics_csv_open(fsi_diagnostics_csv *d, const char *dir, const char *participant,
                             int n_columns, char *const *names, off_t resume, char *msg,
                             size_t msg_size);
/* Appends a row; 0, or -1 with msg (the file then still ends at the last row). */
int fsi_diagnostics_csv_row(fsi_diagnostics_csv *d, double t, const double *values, char *msg,
                            size_t msg_size);
/* Bytes of complete rows so far: what a checkpoint keeps. */
off_t fsi_diagnostics_csv_bytes(const fsi_diagnostics_csv *d);
void fsi_diagnostics_csv_close(fsi_diagnostics_csv *d);

#endif
