/* Preconditioners for the Krylov solvers (core/krylov.h): z = M^-1 r with M close to
 * A and cheap to invert.
 *
 *   - Jacobi: M = diag(A). One multiply per entry, parallel, the weakest.
 *   - ILU(0): M = L U, the incomplete LU factorisation that keeps exactly A's own
 *     sparsity pattern and drops every fill-in (Saad, Iterative Methods for Sparse
 *     Linear Systems, 2nd ed. 2003, Section 10.3.2, Algorithm 10.4). On the
 *     SPH Laplacians of test_krylov it needs 5-6 times fewer BiCGSTAB iterations
 *     than Jacobi. Both the factorisation and the two triangular solves of each
 *     application are sequential by nature (row i needs the rows before it): they run
 *     on one thread whatever the OpenMP setting, which is the price paid for the
 *     fewer iterations (docs/isph.md, "Pressure solve", has the measurement).
 *
 * Set-up refuses a matrix with a zero or missing diagonal entry (Jacobi) or a pivot
 * that vanishes during the factorisation (ILU(0)), with a message: the caller then
 * knows that its matrix is singular or needs another ordering, rather than
 * iterating on infinities. */
#ifndef FSI_PRECONDITIONER_H
#define FSI_PRECONDITIONER_H

#include <stddef.h>
#include <stdint.h>

#include "sparse_matrix.h"

typedef enum { FSI_PRECOND_JACOBI, FSI_PRECOND_ILU0 } fsi_precond_kind;

typedef struct {
    fsi_precond_kind kind;
    int32_t n;
    double *inv_diag;   /* Jacobi: 1 / a_ii */
    fsi_csr lu;         /* ILU(0): L (unit diagonal, not stored) and U in A's pattern */
    int64_t *diag_at;   /* ILU(0): index of each row's diagonal entry in lu */
} fsi_precond;

/* An empty preconditioner; fsi_precond_free releases what a set-up allocated. */
void fsi_precond_init(fsi_precond *m);
void fsi_precond_free(fsi_precond *m);

/* Builds M for the square matrix a (its storage is reused between calls, as the
 * matrix changes every step). 0, or -1 with the reason in err. */
int fsi_precond_setup(fsi_precond *m, fsi_precond_kind kind, const fsi_csr *a, char *err,
                      size_t err_size);

/* z = M^-1 r (n entries each; z and r must not overlap). */
void fsi_precond_apply(const fsi_precond *m, const double *r, double *z);

/* "jacobi" or "ilu0" (for logs and the future case key). */
const char *fsi_precond_name(fsi_precond_kind kind);

#endif
