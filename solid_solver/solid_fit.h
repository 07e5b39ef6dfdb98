/* The weighted least-squares fit of a point's neighbourhood motion, shared by the
 * models that build a deformation gradient from reference neighbours (NOSB-PD's
 * gradient_order, TLSPH's gradient_order): the basis b(xi) is the reference vector xi
 * (a linear fit: 000 Eqs. 34, 36; 003 Eqs. 35-36) or xi and its quadratic monomials
 * (a quadratic fit, whose first FSI_DIM coefficients are the deformation gradient at
 * the point, exact for quadratic fields also where the neighbourhood is one-sided).
 * SOLID_FIT_MAX_BASIS is the quadratic basis's length. */
#ifndef FSI_SOLID_FIT_H
#define FSI_SOLID_FIT_H

#include "dim.h"

#if FSI_DIM == 2
#define SOLID_FIT_MAX_BASIS 5
#else
#define SOLID_FIT_MAX_BASIS 9
#endif

/* b(xi) for a basis of nb = FSI_DIM (linear) or SOLID_FIT_MAX_BASIS (quadratic)
 * functions. The quadratic ones are scaled by 1 / length (the horizon or support) so
 * that every entry of the moment matrix is of order length^2 (its condition number then
 * measures the geometry of the neighbourhood, not the units). */
static inline void solid_fit_basis(const double *xi, double inv_length, int nb, double *b)
{
    for (int d = 0; d < FSI_DIM; d++)
        b[d] = xi[d];
    if (nb == FSI_DIM)
        return;
#if FSI_DIM == 2
    b[2] = xi[0] * xi[0] * inv_length;
    b[3] = xi[0] * xi[1] * inv_length;
    b[4] = xi[1] * xi[1] * inv_length;
#else
    b[3] = xi[0] * xi[0] * inv_length;
    b[4] = xi[1] * xi[1] * inv_length;
    b[5] = xi[2] * xi[2] * inv_length;
    b[6] = xi[0] * xi[1] * inv_length;
    b[7] = xi[1] * xi[2] * inv_length;
    b[8] = xi[2] * xi[0] * inv_length;
#endif
}

/* Inverse of the symmetric n x n moment matrix a (n <= SOLID_FIT_MAX_BASIS) by
 * Gauss-Jordan elimination with partial pivoting, made exactly symmetric. Returns 0,
 * or -1 when a pivot vanishes or the Frobenius condition number |A| |A^-1| exceeds
 * max_condition. */
int solid_fit_inverse(const double *a, int n, double *out, double max_condition);

#endif
