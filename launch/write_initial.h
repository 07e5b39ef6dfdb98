/* `fsi run CASE --check --write-initial`: after the check, each participant's program
 * builds its particles and writes frame 0 (the HDF5 + XDMF of a run, docs/output.md)
 * alone, with FSI_WRITE_INITIAL=1 (core/participant.c: one zero-length window 0
 * without a bus or a coupler), and the run stops there. */
#ifndef FSI_WRITE_INITIAL_H
#define FSI_WRITE_INITIAL_H

#include "run_plan.h"

/* Runs each planned participant in turn in the environment `fsi run` has set
 * (FSI_CASE, FSI_OUT, FSI_RUN_ID), its output in OUT/ROLE.log. Returns 0 when every
 * one wrote its frame, or -1 with a message naming the one that failed. */
int fsi_write_initial_frames(participant_plan *plan, int n_plan, const char *out_dir);

#endif
