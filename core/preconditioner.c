/* Jacobi and ILU(0) preconditioners. */
#include "preconditioner.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grow.h"

void fsi_precond_init(fsi_precond *m)
{
    memset(m, 0, sizeof *m);
    fsi_csr_init(&m->lu);
}

void fsi_precond_free(fsi_precond *m)
{
    free(m->inv_diag);
    free(m->diag_at);
    fsi_csr_free(&m->lu);
    fsi_precond_init(m);
}

const char *fsi_precond_name(fsi_precond_kind kind)
{
    return kind == FSI_PRECOND_ILU0 ? "ilu0" : "jacobi";
}

static int setup_jacobi(fsi_precond *m, const fsi_csr *a, char *err, size_t err_size)
{
    int failed = 0;
    m->inv_diag = fsi_grow(m->inv_diag, (size_t)a->n_rows * sizeof *m->inv_diag, &failed);
    if (failed) {
        snprintf(err, err_size, "jacobi: out of memory for %d rows", (int)a->n_rows);
        return -1;
    }
    fsi_csr_diagonal(a, m->inv_diag);
    for (int32_t i = 0; i < a->n_rows; i++) {
        if (m->inv_diag[i] == 0.0 || !isfinite(m->inv_diag[i])) {
            snprintf(err, err_size, "jacobi: row %d has a zero, missing or non-finite diagonal",
                     (int)i);
            return -1;
        }
        m->inv_diag[i] = 1.0 / m->inv_diag[i];
    }
    return 0;
}

/* The largest |a_ij| of row i: the scale against which a pivot "vanishes". */
static double row_scale(const fsi_csr *a, int32_t i)
{
    double s = 0.0;
    for (int64_t k = a->row_start[i]; k < a->row_start[i + 1]; k++)
        s = fmax(s, fabs(a->val[k]));
    return s;
}

/* ILU(0), IKJ form (Saad 2003, Algorithm 10.4): for each row i and each k < i in
 * row i's pattern, in increasing k, l_ik = a_ik / u_kk and row i -= l_ik * (row k of
 * U), applied only where row i has an entry. `where` maps a column to its position
 * in row i (-1 elsewhere) so that each update is one look-up. */
static int setup_ilu0(fsi_precond *m, const fsi_csr *a, char *err, size_t err_size)
{
    const int32_t n = a->n_rows;
    fsi_csr *lu = &m->lu;
    int failed = 0;
    if (fsi_csr_begin(lu, n, n, a->nnz))
        failed = 1;
    m->diag_at = fsi_grow(m->diag_at, ((size_t)n + 1) * sizeof *m->diag_at, &failed);
    int64_t *where = malloc(((size_t)n + 1) * sizeof *where);
    if (failed || !where) {
        free(where);
        snprintf(err, err_size, "ilu0: out of memory for %d rows", (int)n);
        return -1;
    }
    memcpy(lu->row_start, a->row_start, ((size_t)n + 1) * sizeof *lu->row_start);
    memcpy(lu->col, a->col, (size_t)a->nnz * sizeof *lu->col);
    memcpy(lu->val, a->val, (size_t)a->nnz * sizeof *lu->val);
    lu->nnz = a->nnz;
    lu->rows_built = n;
    for (int32_t j = 0; j < n; j++)
        where[j] = -1;

    int status = 0;
    for (int32_t i = 0; i < n && status == 0; i++) {
        const int64_t begin = lu->row_start[i], end = lu->row_start[i + 1];
        m->diag_at[i] = -1;
        for (int64_t k = begin; k < end; k++) {
            where[lu->col[k]] = k;
            if (lu->col[k] == i)
                m->diag_at[i] = k;
        }
        if (m->diag_at[i] < 0) {
            snprintf(err, err_size, "ilu0: row %d has no diagonal entry", (int)i);
            status = -1;
        }
        for (int64_t k = begin; status == 0 && k < end && lu->col[k] < i; k++) {
            const int32_t row_k = lu->col[k];
            const double l_ik = lu->val[k] / lu->val[m->diag_at[row_k]];
            lu->val[k] = l_ik;
            for (int64_t q = m->diag_at[row_k] + 1; q < lu->row_start[row_k + 1]; q++) {
                const int64_t at = where[lu->col[q]];
                if (at >= 0)
                    lu->val[at] -= l_ik * lu->val[q];
            }
        }
        /* A pivot that is zero to round-off relative to its original row, or not
         * finite, would make U^-1 meaningless. */
        if (status == 0) {
            const double pivot = lu->val[m->diag_at[i]];
            if (!isfinite(pivot) || fabs(pivot) <= 64.0 * DBL_EPSILON * row_scale(a, i)) {
                snprintf(err, err_size, "ilu0: pivot %.3g of row %d vanishes (singular or "
                         "badly ordered matrix)", pivot, (int)i);
                status = -1;
            }
        }
        for (int64_t k = begin; k < end; k++)
            where[lu->col[k]] = -1;
    }
    free(where);
    return status;
}

int fsi_precond_setup(fsi_precond *m, fsi_precond_kind kind, const fsi_csr *a, char *err,
                      size_t err_size)
{
    m->kind = kind;
    m->n = 0;
    if (!fsi_csr_complete(a) || a->n_rows != a->n_cols) {
        snprintf(err, err_size, "%s: the matrix is not square or not completely built",
                 fsi_precond_name(kind));
        return -1;
    }
    const int status = kind == FSI_PRECOND_ILU0 ? setup_ilu0(m, a, err, err_size)
                                                : setup_jacobi(m, a, err, err_size);
    if (status == 0)
        m->n = a->n_rows;
    return status;
}

void fsi_precond_apply(const fsi_precond *m, const double *r, double *z)
{
    const int32_t n = m->n;
    if (m->kind == FSI_PRECOND_JACOBI) {
#pragma omp parallel for schedule(static)
        for (int32_t i = 0; i < n; i++)
            z[i] = m->inv_diag[i] * r[i];
        return;
    }
    /* L y = r (unit diagonal), then U z = y; y lives in z. Sequential: each row uses
     * the rows solved before it. */
    const fsi_csr *lu = &m->lu;
    for (int32_t i = 0; i < n; i++) {
        double s = r[i];
        for (int64_t k = lu->row_start[i]; k < m->diag_at[i]; k++)
            s -= lu->val[k] * z[lu->col[k]];
        z[i] = s;
    }
    for (int32_t i = n - 1; i >= 0; i--) {
        double s = z[i];
        for (int64_t k = m->diag_at[i] + 1; k < lu->row_start[i + 1]; k++)
            s -= lu->val[k] * z[lu->col[k]];
        z[i] = s / lu->val[m->diag_at[i]];
    }
}
