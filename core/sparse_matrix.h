/* A sparse matrix in compressed sparse row (CSR) form, for the linear systems the
 * particle schemes assemble every step (the ISPH pressure Poisson equation, issue #21).
 *
 * Row i holds the entries row_start[i] .. row_start[i + 1] - 1 of col and val, with
 * strictly increasing columns (duplicates summed when the matrix is built): the
 * incomplete LU (core/preconditioner.h) relies on that order to find the diagonal and
 * the strictly lower part of a row. Offsets are 64-bit (a 3D PPE of 10^8 entries fits),
 * column indices 32-bit (unknowns are particles: an int is enough and halves the
 * traffic of the product, which reads one column index per entry).
 *
 * Building, two ways:
 *   - row by row, in order: fsi_csr_begin, then fsi_csr_append_row for rows 0, 1, ...
 *     (what an SPH assembly produces: one particle's neighbours at a time);
 *   - from triplets (i, j, a_ij) in any order: fsi_csr_from_triplets sorts them and
 *     sums duplicates (what a pair loop that adds to both ends produces).
 * A matrix keeps its arrays between builds and only grows them, so rebuilding it every
 * step allocates only while the pattern grows. */
#ifndef FSI_SPARSE_MATRIX_H
#define FSI_SPARSE_MATRIX_H

#include <stdint.h>

typedef struct {
    int32_t n_rows, n_cols;
    int32_t rows_built;   /* rows appended so far (row-by-row building) */
    int64_t *row_start;   /* n_rows + 1 offsets */
    int32_t *col;
    double *val;
    int64_t nnz;
    int64_t row_capacity; /* allocated entries of row_start */
    int64_t capacity;     /* allocated entries of col and val */
} fsi_csr;

/* An empty matrix with no storage; fsi_csr_free releases what a build allocated. */
void fsi_csr_init(fsi_csr *a);
void fsi_csr_free(fsi_csr *a);

/* Starts a row-by-row build of an n_rows x n_cols matrix (any earlier content is
 * dropped, storage kept); nnz_hint (may be 0) reserves entries. 0, or -1 when
 * memory runs out or a size is negative. */
int fsi_csr_begin(fsi_csr *a, int32_t n_rows, int32_t n_cols, int64_t nnz_hint);

/* Appends the next row: count entries (cols[k], vals[k]) in any order; the row is
 * stored sorted by column with duplicates summed. 0, or -1 when all rows are built, a
 * column is out of range or memory runs out (the matrix is then unusable until the
 * next fsi_csr_begin). */
int fsi_csr_append_row(fsi_csr *a, int32_t count, const int32_t *cols, const double *vals);

/* 1 when every row has been appended (the matrix is ready for use). */
int fsi_csr_complete(const fsi_csr *a);

/* Builds the matrix from count triplets (rows[k], cols[k], vals[k]) in any order,
 * duplicates summed. 0, or -1 when an index is out of range or memory runs out. */
int fsi_csr_from_triplets(fsi_csr *a, int32_t n_rows, int32_t n_cols, int64_t count,
                          const int32_t *rows, const int32_t *cols, const double *vals);

/* y = A x (x has n_cols entries, y n_rows; they must not overlap). Rows are shared
 * among the OpenMP threads, each row summed by one thread in column order, so y is
 * the same to the bit for any thread count. */
void fsi_csr_multiply(const fsi_csr *a, const double *x, double *y);

/* diag[i] = a_ii for the first min(n_rows, n_cols) rows, 0 where it is not stored. */
void fsi_csr_diagonal(const fsi_csr *a, double *diag);

/* Index of entry (i, j) in col/val, or -1 when it is not stored (binary search). */
int64_t fsi_csr_find(const fsi_csr *a, int32_t i, int32_t j);

#endif
