/* The next input of a coupling window's fixed point x = H(x) (implicit partitioned
 * coupling): x is the interface motion the solid gives the fluid, n particles of
 * ncomp components each (m = n ncomp values, particle-major), and H(x) the motion
 * the solid ends with after taking the fluid's loads for x. Plain iteration
 * x_next = H(x) diverges when the fluid's added mass exceeds the structure's mass
 * (Causin, Gerbeau & Nobile, CMAME 194 (2005) 4506-4527); these methods make it
 * converge. With r = H(x) - x, the residual:
 *
 *   FSI_ACCEL_CONSTANT  x_next = x + omega0 r.
 *   FSI_ACCEL_AITKEN    x_next = x + omega_i r_i with Aitken's dynamic factor
 *                       (Kuttler & Wall, Comput. Mech. 43 (2008) 61-72):
 *                       omega_0 = omega0 at each window's first iteration, then
 *                       omega_i = -omega_{i-1} (r_{i-1} . (r_i - r_{i-1})) / |r_i - r_{i-1}|^2
 *                       (omega_{i-1} kept when r_i = r_{i-1}).
 *   FSI_ACCEL_IQN_ILS   interface quasi-Newton with an approximation of the inverse
 *                       Jacobian from a least-squares model (Degroote, Bathe &
 *                       Vierendeels, Comput. Struct. 87 (2009) 793-801): with
 *                       xt_i = H(x_i), the columns V = [r_i - r_{i-1}, ...] and
 *                       W = [xt_i - xt_{i-1}, ...], newest first, alpha minimises
 *                       |V alpha + r_i| and x_next = xt_i + W alpha. Without columns
 *                       (first iteration of a window with nothing reused): x + omega0 r.
 *
 * IQN-ILS details:
 *   - The least-squares problem is solved by a QR decomposition of V, rebuilt at every
 *     iteration by modified Gram-Schmidt with one re-orthogonalisation (two passes),
 *     newest column first.
 *   - Filter: while the QR is built, a column whose norm after orthogonalisation
 *     against the columns kept before it is below filter_eps times its norm before
 *     (|v_orth| < filter_eps |v|; a zero column always) is removed from V and W for
 *     good. This relative test during Gram-Schmidt is the filter Haelterman et al.
 *     (Comput. Struct. 171 (2016) 9-17) call QR2; their QR1 tests the diagonal of R
 *     instead (|R_ii| < eps |R|). Newest first, so of a dependent set the oldest goes.
 *   - Reuse: the columns of the last reuse_windows accepted windows (those ended by
 *     fsi_accel_end_window) are kept for the next window, behind its own, which are
 *     newest; differences are only taken within a window. At most max_columns
 *     columns: the oldest beyond that are dropped (and never more than m + 1, which
 *     the filter brings to at most m).
 *   - Columns are differences of interface vectors, so they mean something only for
 *     the same particles in the same order: when a window's id list (or ncomp)
 *     differs from the last window's, the reused columns are dropped.
 * Cost per IQN-ILS iteration: O(m k^2) for k columns, plus 3 m k doubles kept
 * (V, W, Q). Everything is summed in index order on one thread (reproducible). */
#ifndef FSI_COUPLING_ACCELERATION_H
#define FSI_COUPLING_ACCELERATION_H

#include <stddef.h>
#include <stdint.h>

#include "state_store.h"

typedef enum { FSI_ACCEL_CONSTANT, FSI_ACCEL_AITKEN, FSI_ACCEL_IQN_ILS } fsi_accel_kind;

typedef struct {
    fsi_accel_kind kind;
    double omega0;        /* initial / constant relaxation, 0 < omega0 <= 1 */
    int reuse_windows;    /* IQN-ILS: accepted windows whose columns are reused (>= 0) */
    double filter_eps;    /* IQN-ILS: filter threshold, 0 <= filter_eps < 1, e.g. 1e-10 */
    int max_columns;      /* IQN-ILS: at most this many columns (>= 1), oldest dropped */
} fsi_accel_settings;

typedef struct fsi_accel fsi_accel;

/* NULL when out of memory or the settings are invalid (then msg says which; msg may be
 * NULL). omega0 and reuse_windows are checked for every kind, filter_eps and
 * max_columns for IQN-ILS only. */
fsi_accel *fsi_accel_create(const fsi_accel_settings *s, char *msg, size_t msg_size);

/* Starts a window of n particles with ncomp components each (m = n*ncomp values), ids
 * in the order the vectors use. Returns 1 when the id list (or ncomp) differs from the
 * last window's and the reused history was dropped, 0 when not (and for the first
 * window), -1 out of memory or n < 0, ncomp < 1 (no window is then open). A window
 * begun while the last one was not ended was not accepted: its columns are dropped. */
int fsi_accel_begin_window(fsi_accel *a, int n, int ncomp, const int32_t *id);

/* One iteration: x_in was given, x_out = H(x_in) came back; writes the next input into
 * x_next (m values; may alias neither). Returns 0, or -1 when no window is open (the
 * memory was taken by fsi_accel_begin_window). */
int fsi_accel_next(fsi_accel *a, const double *x_in, const double *x_out, double *x_next);

/* The window was accepted (converged or given up): its columns join the reused history,
 * and those of windows more than reuse_windows back leave it. */
void fsi_accel_end_window(fsi_accel *a);

/* Columns in use now (for logs and tests), and the relaxation factor last used:
 * constant, omega0; Aitken, omega_i; IQN-ILS, omega0 after a relaxed step, 0 after a
 * quasi-Newton step. */
int fsi_accel_columns(const fsi_accel *a);
/* Drops every secant pair kept from earlier windows (call before fsi_accel_begin_window):
 * the map they describe has changed (another window length, for one). */
void fsi_accel_drop_history(fsi_accel *a);
double fsi_accel_last_omega(const fsi_accel *a);

/* Everything the acceleration carries from one window to the next (the ids, the
 * reused secant pairs, the counters), under names starting with prefix, into st; and
 * back into a created with the same settings. A restored acceleration goes on exactly
 * as the saved one would have (a coupled checkpoint, docs/checkpoints.md). 0, or -1
 * (memory; restore: an entry missing or of the wrong size). */
int fsi_accel_save(const fsi_accel *a, fsi_state *st, const char *prefix);
int fsi_accel_restore(fsi_accel *a, const fsi_state *st, const char *prefix);

void fsi_accel_free(fsi_accel *a);

#endif
