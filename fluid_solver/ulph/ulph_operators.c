/* The non-local operators of ULPH (000 Eqs. 8-15) over a CSR neighbour list built
 * each evaluation from candidate lists (verlet_list.h): see ulph_operators.h.
 *
 * The build makes two passes over the particles, each parallel with no shared
 * writes: pass 1 counts each particle's candidates within the support (its row
 * length), a serial prefix sum turns the counts into row offsets, pass 2 fills each
 * row (J, w, x_IJ), sums M_I over it (000 Eq. 15), inverts M_I under the rule of the
 * header, and turns x_IJ into g_IJ = w V_J M_I^-1 x_IJ in place. Both passes walk the
 * candidates in their fixed order, so they see the same neighbours in the same order
 * on any thread. */
#include "ulph_operators.h"

#include <stdlib.h>
#include <string.h>

#include "grow.h"

void ulph_operators_init(ulph_operators *ops)
{
    *ops = (ulph_operators){0};
    ops->max_condition = ULPH_MAX_CONDITION_M;
}

void ulph_operators_free(ulph_operators *ops)
{
    const double max_condition = ops->max_condition;
    free(ops->pairs.offset);
    free(ops->pairs.neighbour);
    free(ops->pairs.w);
    free(ops->g);
    free(ops->shape);
    free(ops->shape_inv);
    free(ops->flags);
    ulph_operators_init(ops);
    ops->max_condition = max_condition;
}

/* Room for n particles; 0, or -1 when memory runs out. */
static int reserve_points(ulph_operators *ops, int n)
{
    if (ops->pairs.offset && n <= ops->point_capacity)
        return 0;
    const size_t cap = (size_t)n + (size_t)n / 4 + 16;
    int failed = 0;
    ops->pairs.offset = fsi_grow(ops->pairs.offset, (cap + 1) * sizeof *ops->pairs.offset, &failed);
    ops->shape = fsi_grow(ops->shape, cap * FSI_MAT_SIZE * sizeof *ops->shape, &failed);
    ops->shape_inv = fsi_grow(ops->shape_inv, cap * FSI_MAT_SIZE * sizeof *ops->shape_inv,
                               &failed);
    ops->flags = fsi_grow(ops->flags, cap * sizeof *ops->flags, &failed);
    if (failed)
        return -1;
    ops->point_capacity = (int)cap;
    return 0;
}

/* Room for n_pairs pairs; 0, or -1 when memory runs out. */
static int reserve_pairs(ulph_operators *ops, int64_t n_pairs)
{
    if (ops->g && n_pairs <= ops->pair_capacity)
        return 0;
    const size_t cap = (size_t)n_pairs + (size_t)n_pairs / 4 + 64;
    int failed = 0;
    ops->pairs.neighbour = fsi_grow(ops->pairs.neighbour, cap * sizeof *ops->pairs.neighbour, &failed);
    ops->pairs.w = fsi_grow(ops->pairs.w, cap * sizeof *ops->pairs.w, &failed);
    ops->g = fsi_grow(ops->g, cap * FSI_DIM * sizeof *ops->g, &failed);
    if (failed)
        return -1;
    ops->pair_capacity = (int64_t)cap;
    return 0;
}

/* Largest |M M^-1 - I| (Frobenius) of a usable inverse. fsi_mat_inverse measures
 * the condition as |M| |adj M| / |det M|; for a numerically rank-one 3 x 3 M
 * (collinear neighbours in 3D) adj M and det M are both round-off and their ratio can
 * look benign (five particles on a line: "condition" 8.7). fsi_mat_inverse now also
 * refuses an inverse that misses I by 1e-6; under ULPH's condition bound a usable M
 * meets about |M| |M^-1| 1e-16 < 1e-12, so this tighter bound costs nothing and
 * keeps the rule independent of the general-purpose one. */
#define MAX_INVERSE_RESIDUAL 1e-8

/* M^-1 when M is usable under the rule of the header (apart from the neighbour
 * count): 0, or -1 (m_inv undefined). */
static int shape_inverse(const double *m, double *m_inv, double max_condition)
{
    if (fsi_mat_inverse(m, m_inv, max_condition) != 0)
        return -1;
    double residual[FSI_MAT_SIZE];
    fsi_mat_mul(m, m_inv, residual);
    for (int d = 0; d < FSI_DIM; d++)
        FSI_MAT(residual, d, d) -= 1.0;
    return fsi_mat_norm(residual) <= MAX_INVERSE_RESIDUAL ? 0 : -1;
}

/* Pass 1: the length of particle i's row, its candidates within the support. */
static int64_t row_length(const ulph_operators *ops, const gaussian_kernel *k,
                          const fluid_verlet *list, const double *x, int i)
{
    int64_t count = 0;
    for (int64_t c = list->offset[i]; c < list->offset[i + 1]; c++) {
        double rel[FSI_DIM], r2 = 0.0;
        ulph_pair_vector(ops, x, i, list->candidate[c], rel);
        for (int d = 0; d < FSI_DIM; d++)
            r2 += rel[d] * rel[d];
        count += r2 < k->support2;
    }
    return count;
}

/* Pass 2: fills particle i's row, M_I, M_I^-1 and g; returns 1 when the particle is
 * flagged ULPH_SINGULAR_SHAPE, else 0. */
static int fill_row(ulph_operators *ops, const gaussian_kernel *k, const fluid_verlet *list,
                    const fluid_particles *p, int i)
{
    const double *restrict x = p->x;
    const double *restrict volume = p->volume;
    const int64_t first = ops->pairs.offset[i];
    double m[FSI_MAT_SIZE];
    fsi_mat_zero(m);
    int informative = 0; /* neighbours that add to M: w V_J > 0 at a non-zero distance */

    /* The neighbours within the support, compacted in the candidates' order, with x_IJ
     * in g and r^2 in w for now; then the kernel values in a loop of their own (no
     * call, no gather: the compiler can unroll and vectorise it), then M. */
    int64_t e = first;
    for (int64_t c = list->offset[i]; c < list->offset[i + 1]; c++) {
        const int j = list->candidate[c];
        double rel[FSI_DIM], r2 = 0.0;
        ulph_pair_vector(ops, x, i, j, rel);
        for (int d = 0; d < FSI_DIM; d++)
            r2 += rel[d] * rel[d];
        if (!(r2 < k->support2))
            continue;
        for (int d = 0; d < FSI_DIM; d++)
            ops->g[e * FSI_DIM + d] = rel[d]; /* x_IJ for now, g_IJ below */
        ops->pairs.neighbour[e] = j;
        ops->pairs.w[e] = r2;
        e++;
    }
    const int64_t end = e; /* == offset[i + 1]: pass 1 saw the same neighbours */
    gaussian_kernel_w2_row(k, ops->pairs.w + first, end - first);
    for (int64_t q = first; q < end; q++) {
        const double *rel = ops->g + q * FSI_DIM;
        const double wv = ops->pairs.w[q] * volume[ops->pairs.neighbour[q]];
        double r2 = 0.0;
        for (int d = 0; d < FSI_DIM; d++)
            r2 += rel[d] * rel[d];
        fsi_mat_add_outer(m, wv, rel, rel);     /* 000 Eq. 15 */
        informative += wv > 0.0 && r2 > 0.0;
    }

    /* Exactly symmetric (w V x_a x_b and w V x_b x_a round differently); the adjugate
     * inverse of a symmetric matrix is then exactly symmetric too. */
    for (int r = 0; r < FSI_DIM; r++)
        for (int c = r + 1; c < FSI_DIM; c++)
            FSI_MAT(m, r, c) = FSI_MAT(m, c, r) = 0.5 * (FSI_MAT(m, r, c) + FSI_MAT(m, c, r));
    fsi_mat_copy(m, ops->shape + (int64_t)i * FSI_MAT_SIZE);
    double *m_inv = ops->shape_inv + (int64_t)i * FSI_MAT_SIZE;
    if (list->idle[i]) {
        fsi_mat_zero(m_inv);
        ops->flags[i] = ULPH_IDLE_WALL;
        return 0;
    }
    if (informative < FSI_DIM + 1 || shape_inverse(m, m_inv, ops->max_condition) != 0) {
        fsi_mat_zero(m_inv);
        memset(ops->g + first * FSI_DIM, 0, sizeof(double) * (size_t)((end - first) * FSI_DIM));
        ops->flags[i] = ULPH_SINGULAR_SHAPE;
        return 1;
    }
    ops->flags[i] = 0;
    for (int64_t q2 = first; q2 < end; q2++) {
        double *g = ops->g + q2 * FSI_DIM;
        double rel[FSI_DIM];
        for (int d = 0; d < FSI_DIM; d++)
            rel[d] = ops->pairs.w[q2] * volume[ops->pairs.neighbour[q2]] * g[d];
        fsi_mat_vec(m_inv, rel, g); /* g_IJ = M_I^-1 (w V_J x_IJ) */
    }
    return 0;
}

int ulph_operators_update_list(ulph_operators *ops, const gaussian_kernel *k,
                               const fluid_verlet *list, const fluid_particles *p)
{
    const int n = p->n;
    ops->pairs.n = 0;
    ops->pairs.n_pairs = 0;
    ops->n_singular = 0;
    ops->pairs.periodic = list->periodic;
    if (list->n != n || n < 0 || reserve_points(ops, n) != 0) {
        ulph_operators_free(ops);
        return -1;
    }
    const int parallel = n >= FLUID_PARALLEL_MIN_PARTICLES;
    int64_t *offset = ops->pairs.offset;
    offset[0] = 0;
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (parallel)
    for (int i = 0; i < n; i++)
        offset[i + 1] = row_length(ops, k, list, p->x, i);
    for (int i = 0; i < n; i++)
        offset[i + 1] += offset[i];
    if (reserve_pairs(ops, offset[n]) != 0) {
        ulph_operators_free(ops);
        return -1;
    }
    int n_singular = 0;
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (parallel) reduction(+ : n_singular)
    for (int i = 0; i < n; i++)
        n_singular += fill_row(ops, k, list, p, i);
    ops->pairs.n = n;
    ops->pairs.n_pairs = offset[n];
    ops->n_singular = n_singular;
    return 0;
}

int ulph_operators_update(ulph_operators *ops, const gaussian_kernel *k,
                          const fsi_neighbour_grid *grid, const fluid_particles *p)
{
    fluid_verlet list;
    fluid_verlet_init(&list);
    int rc = fluid_verlet_build(&list, grid, p, k->support, 0);
    if (rc == 0)
        rc = ulph_operators_update_list(ops, k, &list, p);
    else
        ulph_operators_free(ops);
    fluid_verlet_free(&list);
    return rc;
}

void ulph_gradient_scalar(const ulph_operators *ops, const double *f, double *grad)
{
    const int n = ops->pairs.n;
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        double s[FSI_DIM] = {0};
        if (!(ops->flags[i] & ULPH_SINGULAR_SHAPE)) {
            const double fi = f[i];
            for (int64_t q = ops->pairs.offset[i]; q < ops->pairs.offset[i + 1]; q++) {
                const double df = f[ops->pairs.neighbour[q]] - fi;
                const double *g = ops->g + q * FSI_DIM;
                for (int d = 0; d < FSI_DIM; d++)
                    s[d] += df * g[d];
            }
        }
        for (int d = 0; d < FSI_DIM; d++)
            grad[(int64_t)i * FSI_DIM + d] = s[d];
    }
}

void ulph_gradient_vector(const ulph_operators *ops, const double *u, double *grad)
{
    const int n = ops->pairs.n;
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        double s[FSI_MAT_SIZE] = {0};
        if (!(ops->flags[i] & ULPH_SINGULAR_SHAPE)) {
            const double *ui = u + (int64_t)i * FSI_DIM;
            for (int64_t q = ops->pairs.offset[i]; q < ops->pairs.offset[i + 1]; q++) {
                const double *uj = u + (int64_t)ops->pairs.neighbour[q] * FSI_DIM;
                double du[FSI_DIM];
                for (int a = 0; a < FSI_DIM; a++)
                    du[a] = uj[a] - ui[a];
                fsi_mat_add_outer(s, 1.0, du, ops->g + q * FSI_DIM);
            }
        }
        fsi_mat_copy(s, grad + (int64_t)i * FSI_MAT_SIZE);
    }
}

void ulph_divergence(const ulph_operators *ops, const double *u, double *div)
{
    const int n = ops->pairs.n;
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        double s = 0.0;
        if (!(ops->flags[i] & ULPH_SINGULAR_SHAPE)) {
            const double *ui = u + (int64_t)i * FSI_DIM;
            for (int64_t q = ops->pairs.offset[i]; q < ops->pairs.offset[i + 1]; q++) {
                const double *uj = u + (int64_t)ops->pairs.neighbour[q] * FSI_DIM;
                const double *g = ops->g + q * FSI_DIM;
                for (int a = 0; a < FSI_DIM; a++)
                    s += (uj[a] - ui[a]) * g[a];
            }
        }
        div[i] = s;
    }
}
