/* Matrices that look like a pressure Poisson equation, for the sparse solver tests:
 *
 *   unit_laplace5: the 5-point Laplacian -(d2/dx2 + d2/dy2) h^2 on the n x n interior
 *     points of a grid with Dirichlet boundary (eliminated): 4 on the diagonal, -1 to
 *     each neighbour; symmetric positive definite, condition number about
 *     4 (n + 1)^2 / pi^2.
 *   unit_sph_laplace: an SPH Laplacian on an m x m lattice of spacing 1, each point
 *     moved by up to `jitter` in x and y, in Brookshaw's form (Brookshaw 1985;
 *     Cummins & Rudman 1999 use it for the ISPH PPE): (L p)_i = sum_j c_ij (p_i - p_j)
 *     with c_ij = -2 W'(r_ij) / r_ij, W the Wendland C2 kernel (2D) with h = 1.3,
 *     support 2h = 2.6: about 20 neighbours. c_ij = (1 - q/2)^3 up to a constant
 *     (W'(q) = -5 q (1 - q/2)^3 times a constant for q = r/h). Row sums are zero, so
 *     the operator is singular until Dirichlet rows pin it. `skew` mimics the
 *     corrected operators of ISPH, which make it non-symmetric: each c_ij is scaled by
 *     1 + skew (e_ij . g_i) with e_ij the unit vector to j and g_i a random unit vector
 *     of row i (skew < 1 keeps every c_ij positive: an M-matrix-like operator).
 *     With `dirichlet`, the outer ring of points (the "free surface") are rows
 *     p_i = b_i (identity rows, the couplings to them kept in the other rows):
 *     nonsingular. */
#ifndef FSI_UNIT_PPE_MATRICES_H
#define FSI_UNIT_PPE_MATRICES_H

#include <math.h>

#include "sparse_matrix.h"
#include "unit_random.h"

static inline int unit_laplace5(fsi_csr *a, int n)
{
    if (fsi_csr_begin(a, n * n, n * n, 5LL * n * n))
        return -1;
    for (int y = 0; y < n; y++)
        for (int x = 0; x < n; x++) {
            int32_t c[5];
            double v[5];
            int k = 0;
            c[k] = y * n + x, v[k++] = 4.0;
            if (x > 0)
                c[k] = y * n + x - 1, v[k++] = -1.0;
            if (x < n - 1)
                c[k] = y * n + x + 1, v[k++] = -1.0;
            if (y > 0)
                c[k] = (y - 1) * n + x, v[k++] = -1.0;
            if (y < n - 1)
                c[k] = (y + 1) * n + x, v[k++] = -1.0;
            if (fsi_csr_append_row(a, k, c, v))
                return -1;
        }
    return 0;
}

/* Point (x, y) of the lattice is unknown y * m + x. The neighbours of a point lie
 * within 3 lattice steps (2h + 2 jitter = 2.6 + 0.2 < 3), so no search is needed. */
static inline int unit_sph_laplace(fsi_csr *a, int m, double jitter, double skew,
                                   int dirichlet, uint64_t seed)
{
    const int n = m * m;
    const double h = 1.3, support = 2.0 * h;
    double *pos = malloc(2 * (size_t)n * sizeof *pos), *g = malloc(2 * (size_t)n * sizeof *g);
    for (int i = 0; i < n; i++) {
        pos[2 * i] = i % m + jitter * (2.0 * unit_uniform(&seed) - 1.0);
        pos[2 * i + 1] = i / m + jitter * (2.0 * unit_uniform(&seed) - 1.0);
        const double angle = 2.0 * M_PI * unit_uniform(&seed);
        g[2 * i] = cos(angle);
        g[2 * i + 1] = sin(angle);
    }
    int status = fsi_csr_begin(a, n, n, 24LL * n);
    for (int i = 0; i < n && status == 0; i++) {
        const int xi = i % m, yi = i / m;
        int32_t c[64];
        double v[64];
        int k = 1;
        c[0] = i;
        v[0] = dirichlet && (xi == 0 || yi == 0 || xi == m - 1 || yi == m - 1) ? 1.0 : 0.0;
        if (v[0] == 0.0) {
            for (int dy = -3; dy <= 3; dy++)
                for (int dx = -3; dx <= 3; dx++) {
                    const int xj = xi + dx, yj = yi + dy, j = yj * m + xj;
                    if ((dx == 0 && dy == 0) || xj < 0 || yj < 0 || xj >= m || yj >= m)
                        continue;
                    const double rx = pos[2 * j] - pos[2 * i], ry = pos[2 * j + 1] - pos[2 * i + 1];
                    const double r = sqrt(rx * rx + ry * ry), q = r / h;
                    if (r >= support)
                        continue;
                    const double e_dot_g = (rx * g[2 * i] + ry * g[2 * i + 1]) / r;
                    const double cij = pow(1.0 - 0.5 * q, 3) * (1.0 + skew * e_dot_g);
                    c[k] = j;
                    v[k++] = -cij;
                    v[0] += cij;
                }
        }
        status = fsi_csr_append_row(a, k, c, v);
    }
    free(pos);
    free(g);
    return status;
}

#endif
