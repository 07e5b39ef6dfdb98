/* CSR matrix: building (row by row or from triplets), product, diagonal. */
#include "sparse_matrix.h"

#include <stdlib.h>
#include <string.h>

#include "grow.h"

void fsi_csr_init(fsi_csr *a)
{
    memset(a, 0, sizeof *a);
}

void fsi_csr_free(fsi_csr *a)
{
    free(a->row_start);
    free(a->col);
    free(a->val);
    fsi_csr_init(a);
}

static int reserve_rows(fsi_csr *a, int32_t n_rows)
{
    if ((int64_t)n_rows + 1 <= a->row_capacity)
        return 0;
    int failed = 0;
    a->row_start = fsi_grow(a->row_start, ((size_t)n_rows + 1) * sizeof *a->row_start, &failed);
    if (failed)
        return -1;
    a->row_capacity = (int64_t)n_rows + 1;
    return 0;
}

static int reserve_entries(fsi_csr *a, int64_t entries)
{
    if (entries <= a->capacity && a->col)   /* always some storage: no NULL to memcpy */
        return 0;
    const size_t want = fsi_grown_capacity((size_t)entries);
    int failed = 0;
    a->col = fsi_grow(a->col, want * sizeof *a->col, &failed);
    a->val = fsi_grow(a->val, want * sizeof *a->val, &failed);
    if (failed)
        return -1;
    a->capacity = (int64_t)want;
    return 0;
}

int fsi_csr_begin(fsi_csr *a, int32_t n_rows, int32_t n_cols, int64_t nnz_hint)
{
    a->n_rows = a->n_cols = a->rows_built = 0;
    a->nnz = 0;
    if (n_rows < 0 || n_cols < 0 || nnz_hint < 0)
        return -1;
    if (reserve_rows(a, n_rows) || reserve_entries(a, nnz_hint))
        return -1;
    a->n_rows = n_rows;
    a->n_cols = n_cols;
    a->row_start[0] = 0;
    return 0;
}

/* Sorts the n entries (c, v) of one row by column and sums equal columns; returns the
 * number left. Insertion sort: a particle's row holds a few tens of entries, where it
 * beats the general sorts, and it is stable, so duplicates are summed in the order
 * they were given (the same sum on every run). */
static int64_t sort_and_sum(int32_t *c, double *v, int64_t n)
{
    for (int64_t k = 1; k < n; k++) {
        const int32_t ck = c[k];
        const double vk = v[k];
        int64_t m = k;
        for (; m > 0 && c[m - 1] > ck; m--) {
            c[m] = c[m - 1];
            v[m] = v[m - 1];
        }
        c[m] = ck;
        v[m] = vk;
    }
    int64_t kept = 0;
    for (int64_t k = 0; k < n; k++) {
        if (kept > 0 && c[kept - 1] == c[k]) {
            v[kept - 1] += v[k];
        } else {
            c[kept] = c[k];
            v[kept] = v[k];
            kept++;
        }
    }
    return kept;
}

int fsi_csr_append_row(fsi_csr *a, int32_t count, const int32_t *cols, const double *vals)
{
    if (a->rows_built >= a->n_rows || count < 0)
        return -1;
    for (int32_t k = 0; k < count; k++)
        if (cols[k] < 0 || cols[k] >= a->n_cols)
            return -1;
    if (reserve_entries(a, a->nnz + count))
        return -1;
    int32_t *c = a->col + a->nnz;
    double *v = a->val + a->nnz;
    memcpy(c, cols, (size_t)count * sizeof *c);
    memcpy(v, vals, (size_t)count * sizeof *v);
    a->nnz += sort_and_sum(c, v, count);
    a->rows_built++;
    a->row_start[a->rows_built] = a->nnz;
    return 0;
}

int fsi_csr_complete(const fsi_csr *a)
{
    return a->row_start != NULL && a->rows_built == a->n_rows;
}

int fsi_csr_from_triplets(fsi_csr *a, int32_t n_rows, int32_t n_cols, int64_t count,
                          const int32_t *rows, const int32_t *cols, const double *vals)
{
    if (count < 0 || fsi_csr_begin(a, n_rows, n_cols, count))
        return -1;
    for (int64_t k = 0; k < count; k++)
        if (rows[k] < 0 || rows[k] >= n_rows || cols[k] < 0 || cols[k] >= n_cols)
            return -1;
    /* Counting sort by row (stable), into the final arrays. */
    int64_t *start = a->row_start;
    memset(start, 0, ((size_t)n_rows + 1) * sizeof *start);
    for (int64_t k = 0; k < count; k++)
        start[rows[k] + 1]++;
    for (int32_t i = 0; i < n_rows; i++)
        start[i + 1] += start[i];
    int64_t *next = malloc(((size_t)n_rows + 1) * sizeof *next);
    if (!next)
        return -1;
    memcpy(next, start, ((size_t)n_rows + 1) * sizeof *next);
    for (int64_t k = 0; k < count; k++) {
        const int64_t at = next[rows[k]]++;
        a->col[at] = cols[k];
        a->val[at] = vals[k];
    }
    free(next);
    /* Sort each row by column and sum duplicates, compacting in place (the write
     * position never passes the read position). */
    int64_t written = 0;
    for (int32_t i = 0; i < n_rows; i++) {
        const int64_t from = start[i], n = start[i + 1] - from;
        const int64_t kept = sort_and_sum(a->col + from, a->val + from, n);
        memmove(a->col + written, a->col + from, (size_t)kept * sizeof *a->col);
        memmove(a->val + written, a->val + from, (size_t)kept * sizeof *a->val);
        start[i] = written;
        written += kept;
    }
    start[n_rows] = written;
    a->nnz = written;
    a->rows_built = n_rows;
    return 0;
}

void fsi_csr_multiply(const fsi_csr *a, const double *x, double *y)
{
    const int64_t *start = a->row_start;
    const int32_t *col = a->col;
    const double *val = a->val;
    /* static schedule: rows are of similar length, and each row's sum is one thread's
     * loop in column order, which is what makes y independent of the thread count. */
#pragma omp parallel for schedule(static)
    for (int32_t i = 0; i < a->n_rows; i++) {
        double s = 0.0;
        for (int64_t k = start[i]; k < start[i + 1]; k++)
            s += val[k] * x[col[k]];
        y[i] = s;
    }
}

int64_t fsi_csr_find(const fsi_csr *a, int32_t i, int32_t j)
{
    int64_t lo = a->row_start[i], hi = a->row_start[i + 1];
    while (lo < hi) {
        const int64_t mid = lo + (hi - lo) / 2;
        if (a->col[mid] < j)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < a->row_start[i + 1] && a->col[lo] == j ? lo : -1;
}

void fsi_csr_diagonal(const fsi_csr *a, double *diag)
{
    const int32_t n = a->n_rows < a->n_cols ? a->n_rows : a->n_cols;
    for (int32_t i = 0; i < n; i++) {
        const int64_t k = fsi_csr_find(a, i, i);
        diag[i] = k >= 0 ? a->val[k] : 0.0;
    }
}
