/* Krylov solvers for A x = b with a general (non-symmetric) sparse A: the ISPH
 * pressure Poisson equation (issue #21), whose corrected operators make A
 * non-symmetric, so conjugate gradients do not apply.
 *
 * fsi_bicgstab: BiCGSTAB (H. A. van der Vorst, SIAM J. Sci. Stat. Comput. 13 (1992)
 * 631-644), right-preconditioned as in Barrett et al., Templates for the Solution of
 * Linear Systems (SIAM 1994), Fig. 2.10: two products with A and two applications of
 * M^-1 per iteration, no stored Krylov basis.
 *
 * Contract:
 *   - x on entry is the first guess (warm start: the last step's pressure); on
 *     return the solution, or, when not converged, the iterate with the smallest
 *     residual met (never worse than the guess, never NaN).
 *   - converged when ||b - A x|| / s <= tol (2-norms), s = max(||b||, ||A x0||),
 *     checked on the TRUE residual: the recursively updated one drifts from it by
 *     round-off, so when the recursion says "converged" the residual is recomputed
 *     and the iteration goes on from it if it is not. s is ||b|| but when the guess's
 *     image is larger: a right-hand side that cancels to round-off (ISPH's water
 *     falling with a heavy plate at t = 0, every source zero) makes tol ||b||
 *     unattainable, and the pressure field the guess holds is then the scale the
 *     answer's error is measured against. b = 0 gives x = 0, converged, 0 iterations.
 *   - breakdown: rho = (r0, r) or (r0, A p) or omega vanishing (below the dot
 *     product's own round-off, eps |u| |v|). The solver restarts once from the
 *     current x with a new shadow residual r0 = b - A x; a second breakdown ends it
 *     with converged = 0 and the reason. So does divergence: once eps ||r|| exceeds
 *     tol s the round-off of the updates alone keeps the residual above the goal
 *     (reason "diverged"). A singular system with no solution (an inconsistent
 *     right-hand side, e.g. a PPE with no Dirichlet particle) ends so or at max_iter.
 *     A singular but consistent one may converge to one of its solutions: the
 *     Dirichlet set is the caller's to provide.
 * The products with A use OpenMP (fsi_csr_multiply); the dot products are summed in
 * index order on one thread, the Jacobi apply is per entry and ILU(0) runs on one
 * thread, so the iterates do not depend on the thread count. */
#ifndef FSI_KRYLOV_H
#define FSI_KRYLOV_H

#include "preconditioner.h"
#include "sparse_matrix.h"

typedef struct {
    double tol;      /* relative residual to reach, e.g. 1e-8 */
    int max_iter;    /* iterations (each: two products with A) before giving up */
} fsi_krylov_settings;

typedef struct {
    int iterations;        /* iterations done, over all restarts */
    double rel_residual;   /* ||b - A x|| / s of the returned x (recomputed) */
    int converged;         /* 1 when rel_residual <= tol */
    int restarts;          /* BiCGSTAB's breakdown restarts (0 or 1) */
    const char *reason;    /* why it stopped: "converged", "max_iter", a breakdown or
                              "diverged" (static strings) */
} fsi_krylov_result;

/* Solves A x = b with preconditioner m (set up for this A). A square and complete. */
fsi_krylov_result fsi_bicgstab(const fsi_csr *a, const fsi_precond *m, const double *b,
                               double *x, const fsi_krylov_settings *settings);

/* fsi_gmres (core/gmres.c): restarted GMRES(m) (Saad & Schultz, SIAM J. Sci. Stat.
 * Comput. 7 (1986) 856-869), right-preconditioned (Saad, Iterative Methods for Sparse
 * Linear Systems, 2nd ed. 2003, Algorithm 9.5), the least-squares problem of each
 * cycle reduced by Givens rotations as the basis grows. One product with A per
 * iteration (BiCGSTAB: two), restart + 1 vectors of n. The same contract as
 * fsi_bicgstab: warm start, stop on the true residual at the end of a cycle, no NaN.
 * Within a cycle the residual cannot rise, so x is never worse than the guess; it
 * gives up when a cycle lowers the true residual by less than 0.1 % (what a system
 * without solution does: "stagnated") or when the Hessenberg matrix turns singular
 * ("breakdown"); restarts counts nothing here. */
fsi_krylov_result fsi_gmres(const fsi_csr *a, const fsi_precond *m, const double *b,
                            double *x, const fsi_krylov_settings *settings, int restart);

#endif
