/* The direct reference for the Krylov tests: SuiteSparse's UMFPACK sparse LU
 * (T. A. Davis, ACM TOMS 30 (2004) 196-199), Debian's libsuitesparse-dev. Only the
 * tests link it (tests/CMakeLists.txt).
 *
 * UMFPACK takes compressed columns; our CSR arrays read as compressed columns are
 * A^T, so A x = b is UMFPACK's transposed solve (UMFPACK_At) and A^T x = b its plain
 * one (UMFPACK_A). */
#ifndef FSI_UNIT_UMFPACK_H
#define FSI_UNIT_UMFPACK_H

#include <stdlib.h>
#include <umfpack.h>

#include "sparse_matrix.h"

typedef struct {
    int n;
    int *ap, *ai;       /* row_start and col as int, as umfpack_di_* wants */
    const double *ax;
    void *numeric;
    double info[UMFPACK_INFO];
} unit_lu;

/* Factors a (square); 0, or UMFPACK's status. */
static inline int unit_lu_factor(unit_lu *lu, const fsi_csr *a)
{
    lu->n = a->n_rows;
    lu->ap = malloc(((size_t)a->n_rows + 1) * sizeof *lu->ap);
    lu->ai = malloc(((size_t)a->nnz + 1) * sizeof *lu->ai);
    lu->ax = a->val;
    lu->numeric = NULL;
    for (int i = 0; i <= a->n_rows; i++)
        lu->ap[i] = (int)a->row_start[i];
    for (int64_t k = 0; k < a->nnz; k++)
        lu->ai[k] = a->col[k];
    void *symbolic = NULL;
    int status = umfpack_di_symbolic(lu->n, lu->n, lu->ap, lu->ai, lu->ax, &symbolic, NULL,
                                     lu->info);
    if (status == UMFPACK_OK)
        status = umfpack_di_numeric(lu->ap, lu->ai, lu->ax, symbolic, &lu->numeric, NULL,
                                    lu->info);
    umfpack_di_free_symbolic(&symbolic);
    return status;
}

/* x = A^-1 b (transposed = 0) or A^-T b (transposed = 1); 0 or UMFPACK's status. */
static inline int unit_lu_solve(unit_lu *lu, const double *b, double *x, int transposed)
{
    return umfpack_di_solve(transposed ? UMFPACK_A : UMFPACK_At, lu->ap, lu->ai, lu->ax, x, b,
                            lu->numeric, NULL, lu->info);
}

static inline void unit_lu_free(unit_lu *lu)
{
    if (lu->numeric)
        umfpack_di_free_numeric(&lu->numeric);
    free(lu->ap);
    free(lu->ai);
}

#endif
