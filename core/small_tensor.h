/* FSI_DIM x FSI_DIM matrices and FSI_DIM vectors for per-particle kinematics
 * (shape tensors, deformation gradients, stresses): plain double arrays, matrices
 * row-major (a[i * FSI_DIM + j] is row i, column j), all functions inline so that
 * the compiler unrolls the fixed-size loops. Outputs may not alias inputs unless a
 * function says so. */
#ifndef FSI_SMALL_TENSOR_H
#define FSI_SMALL_TENSOR_H

#include <math.h>

#include "dim.h"

#define FSI_MAT_SIZE (FSI_DIM * FSI_DIM)
#define FSI_MAT(a, i, j) ((a)[(i) * FSI_DIM + (j)])

static inline void fsi_mat_zero(double *restrict a)
{
    for (int k = 0; k < FSI_MAT_SIZE; k++)
        a[k] = 0.0;
}

static inline void fsi_mat_identity(double *restrict a)
{
    for (int i = 0; i < FSI_DIM; i++)
        for (int j = 0; j < FSI_DIM; j++)
            FSI_MAT(a, i, j) = (i == j) ? 1.0 : 0.0;
}

static inline void fsi_mat_copy(const double *restrict a, double *restrict out)
{
    for (int k = 0; k < FSI_MAT_SIZE; k++)
        out[k] = a[k];
}

/* out = a b */
static inline void fsi_mat_mul(const double *restrict a, const double *restrict b,
                               double *restrict out)
{
    for (int i = 0; i < FSI_DIM; i++)
        for (int j = 0; j < FSI_DIM; j++) {
            double s = 0.0;
            for (int k = 0; k < FSI_DIM; k++)
                s += FSI_MAT(a, i, k) * FSI_MAT(b, k, j);
            FSI_MAT(out, i, j) = s;
        }
}

/* out = a b^T */
static inline void fsi_mat_mul_transpose(const double *restrict a, const double *restrict b,
                                         double *restrict out)
{
    for (int i = 0; i < FSI_DIM; i++)
        for (int j = 0; j < FSI_DIM; j++) {
            double s = 0.0;
            for (int k = 0; k < FSI_DIM; k++)
                s += FSI_MAT(a, i, k) * FSI_MAT(b, j, k);
            FSI_MAT(out, i, j) = s;
        }
}

/* out = a^T b */
static inline void fsi_mat_transpose_mul(const double *restrict a, const double *restrict b,
                                         double *restrict out)
{
    for (int i = 0; i < FSI_DIM; i++)
        for (int j = 0; j < FSI_DIM; j++) {
            double s = 0.0;
            for (int k = 0; k < FSI_DIM; k++)
                s += FSI_MAT(a, k, i) * FSI_MAT(b, k, j);
            FSI_MAT(out, i, j) = s;
        }
}

static inline void fsi_mat_transpose(const double *restrict a, double *restrict out)
{
    for (int i = 0; i < FSI_DIM; i++)
        for (int j = 0; j < FSI_DIM; j++)
            FSI_MAT(out, i, j) = FSI_MAT(a, j, i);
}

/* out = a v */
static inline void fsi_mat_vec(const double *restrict a, const double *restrict v,
                               double *restrict out)
{
    for (int i = 0; i < FSI_DIM; i++) {
        double s = 0.0;
        for (int k = 0; k < FSI_DIM; k++)
            s += FSI_MAT(a, i, k) * v[k];
        out[i] = s;
    }
}

/* a += s (u outer v), i.e. a_ij += s u_i v_j */
static inline void fsi_mat_add_outer(double *restrict a, double s, const double *restrict u,
                                     const double *restrict v)
{
    for (int i = 0; i < FSI_DIM; i++) {
        const double su = s * u[i];
        for (int j = 0; j < FSI_DIM; j++)
            FSI_MAT(a, i, j) += su * v[j];
    }
}

/* out = a + s b (out may alias a or b) */
static inline void fsi_mat_axpy(const double *a, double s, const double *b, double *out)
{
    for (int k = 0; k < FSI_MAT_SIZE; k++)
        out[k] = a[k] + s * b[k];
}

static inline void fsi_mat_scale(double *a, double s)
{
    for (int k = 0; k < FSI_MAT_SIZE; k++)
        a[k] *= s;
}

/* Symmetric part (a + a^T) / 2 and skew part (a - a^T) / 2. */
static inline void fsi_mat_sym(const double *restrict a, double *restrict out)
{
    for (int i = 0; i < FSI_DIM; i++)
        for (int j = 0; j < FSI_DIM; j++)
            FSI_MAT(out, i, j) = 0.5 * (FSI_MAT(a, i, j) + FSI_MAT(a, j, i));
}

static inline void fsi_mat_skew(const double *restrict a, double *restrict out)
{
    for (int i = 0; i < FSI_DIM; i++)
        for (int j = 0; j < FSI_DIM; j++)
            FSI_MAT(out, i, j) = 0.5 * (FSI_MAT(a, i, j) - FSI_MAT(a, j, i));
}

/* Frobenius norm. */
static inline double fsi_mat_norm(const double *a)
{
    double s = 0.0;
    for (int k = 0; k < FSI_MAT_SIZE; k++)
        s += a[k] * a[k];
    return sqrt(s);
}

static inline double fsi_mat_trace(const double *a)
{
    double t = 0.0;
    for (int d = 0; d < FSI_DIM; d++)
        t += FSI_MAT(a, d, d);
    return t;
}

static inline double fsi_mat_det(const double *a)
{
#if FSI_DIM == 2
    return a[0] * a[3] - a[1] * a[2];
#else
    return a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) +
           a[2] * (a[3] * a[7] - a[4] * a[6]);
#endif
}

/* Inverse by the adjugate. Returns 0, or -1 (out untouched) when a is singular, not
 * finite, or ill-conditioned: when the Frobenius condition number
 * |a| |a^-1| exceeds max_condition (at least FSI_DIM for any matrix; pass e.g. 1e8),
 * or when a a^-1 misses I by more than 1e-6 in any entry (numerically rank-deficient). */
static inline int fsi_mat_inverse(const double *restrict a, double *restrict out,
                                  double max_condition)
{
    double adj[FSI_MAT_SIZE];
#if FSI_DIM == 2
    adj[0] = a[3];
    adj[1] = -a[1];
    adj[2] = -a[2];
    adj[3] = a[0];
#else
    adj[0] = a[4] * a[8] - a[5] * a[7];
    adj[1] = a[2] * a[7] - a[1] * a[8];
    adj[2] = a[1] * a[5] - a[2] * a[4];
    adj[3] = a[5] * a[6] - a[3] * a[8];
    adj[4] = a[0] * a[8] - a[2] * a[6];
    adj[5] = a[2] * a[3] - a[0] * a[5];
    adj[6] = a[3] * a[7] - a[4] * a[6];
    adj[7] = a[1] * a[6] - a[0] * a[7];
    adj[8] = a[0] * a[4] - a[1] * a[3];
#endif
    const double det = fsi_mat_det(a);
    if (!(det != 0.0) || !isfinite(det))
        return -1;
    /* |a| |a^-1| = |a| |adj| / |det|: compare without dividing by a tiny det. */
    const double na = fsi_mat_norm(a), nadj = fsi_mat_norm(adj);
    if (!isfinite(na) || !isfinite(nadj) || na * nadj > max_condition * fabs(det))
        return -1;
    const double r = 1.0 / det;
    double inv[FSI_MAT_SIZE];
    for (int k = 0; k < FSI_MAT_SIZE; k++)
        inv[k] = adj[k] * r;
    /* A rank-deficient 3x3 matrix can pass the test above: its det and adjugate are
     * both round-off, and their ratio need not be large (five collinear points gave
     * a "condition number" of 8.7). Such an inverse does not invert: check
     * a a^-1 = I, which a genuine inverse meets to about cond * 1e-16. */
    for (int i = 0; i < FSI_DIM; i++)
        for (int j = 0; j < FSI_DIM; j++) {
            double t = -(double)(i == j);
            for (int k = 0; k < FSI_DIM; k++)
                t += FSI_MAT(a, i, k) * FSI_MAT(inv, k, j);
            if (!(fabs(t) <= 1e-6))
                return -1;
        }
    for (int k = 0; k < FSI_MAT_SIZE; k++)
        out[k] = inv[k];
    return 0;
}

/* Solves a x = b. Returns 0, or -1 under the conditions of fsi_mat_inverse. */
static inline int fsi_mat_solve(const double *restrict a, const double *restrict b,
                                double *restrict x, double max_condition)
{
    double inv[FSI_MAT_SIZE];
    if (fsi_mat_inverse(a, inv, max_condition) != 0)
        return -1;
    fsi_mat_vec(inv, b, x);
    return 0;
}

/* Double contraction a : b = sum_ij a_ij b_ij. */
static inline double fsi_mat_ddot(const double *a, const double *b)
{
    double s = 0.0;
    for (int k = 0; k < FSI_MAT_SIZE; k++)
        s += a[k] * b[k];
    return s;
}

static inline double fsi_vec_dot(const double *a, const double *b)
{
    double s = 0.0;
    for (int i = 0; i < FSI_DIM; i++)
        s += a[i] * b[i];
    return s;
}

static inline double fsi_vec_norm(const double *a)
{
    return sqrt(fsi_vec_dot(a, a));
}

/* Symmetric 3D tensors in the material order xx, yy, zz, xy, yz, zx (tensor shear
 * components, solid_solver/materials/material.h). In a 2D build the components
 * with a z index are the out-of-plane ones. */
/* Index (0..5) of component (i, j), i, j in 0..2. */
static inline int fsi_voigt_index(int i, int j)
{
    if (i == j)
        return i;
    const int s = i + j; /* 1: xy, 3: yz, 2: zx */
    return s == 1 ? 3 : (s == 3 ? 4 : 5);
}

/* The FSI_DIM x FSI_DIM block of a 6-component tensor, and back (out-of-plane
 * components of t6 are left as they are). */
static inline void fsi_sym6_to_mat(const double *restrict t6, double *restrict a)
{
    for (int i = 0; i < FSI_DIM; i++)
        for (int j = 0; j < FSI_DIM; j++)
            FSI_MAT(a, i, j) = t6[fsi_voigt_index(i, j)];
}

static inline void fsi_mat_to_sym6(const double *restrict a, double *restrict t6)
{
    for (int i = 0; i < FSI_DIM; i++)
        for (int j = i; j < FSI_DIM; j++)
            t6[fsi_voigt_index(i, j)] = 0.5 * (FSI_MAT(a, i, j) + FSI_MAT(a, j, i));
}

/* a : b for two 6-component symmetric tensors (shear terms count twice). */
static inline double fsi_sym6_ddot(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] +
           2.0 * (a[3] * b[3] + a[4] * b[4] + a[5] * b[5]);
}

/* t6 <- R t6 R^T for a FSI_DIM x FSI_DIM rotation R (in 2D the z axis is fixed). */
static inline void fsi_sym6_rotate(const double *restrict r, double *restrict t6)
{
    double r3[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int i = 0; i < FSI_DIM; i++)
        for (int j = 0; j < FSI_DIM; j++)
            r3[i][j] = FSI_MAT(r, i, j);
    double t[3][3], rt[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            t[i][j] = t6[fsi_voigt_index(i, j)];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double s = 0.0;
            for (int k = 0; k < 3; k++)
                s += r3[i][k] * t[k][j];
            rt[i][j] = s;
        }
    for (int i = 0; i < 3; i++)
        for (int j = i; j < 3; j++) {
            double s = 0.0;
            for (int k = 0; k < 3; k++)
                s += rt[i][k] * r3[j][k];
            t6[fsi_voigt_index(i, j)] = s;
        }
}

#endif
