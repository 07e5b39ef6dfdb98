/* OUT/run.xmf: one file that opens every participant's particles together in ParaView
 * (docs/output.md, "Fluid and solid together"). It includes each participant's
 * sidecar NAME.xmf (core/h5_output.h) with XInclude, so it never changes while the run
 * writes: what it shows is what the sidecars list when it is opened, and it stays
 * right after `fsi run --restart`, which rebuilds the sidecars. */
#ifndef FSI_RUN_XMF_H
#define FSI_RUN_XMF_H

/* Writes DIR/run.xmf including DIR/<names[i]>.xmf, i < n, in that order (written
 * under a temporary name and renamed). Returns 0, or -1 with a message on stderr
 * naming the file and the reason. */
int fsi_write_run_xmf(const char *dir, const char *const *names, int n);

#endif
