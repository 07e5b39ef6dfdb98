/* The non-local operators of ULPH (000 Eqs. 8-15) over pair-once rows derived from
 * candidate lists (fluid_rows.h): see ulph_operators.h.
 *
 * An update filters the rows to the pairs within the support and turns their r^2 into
 * w in a loop of its own (gaussian_kernel_w2_row: no call, no branch), then sums M over
 * the pairs in blocks (each fluid pair once, added to both particles), then inverts
 * each M_I under the rule of the header. */
#include "ulph_operators.h"

#include <stdlib.h>
#include <string.h>

#include "always_inline.h"
#include "grow.h"

void ulph_operators_init(ulph_operators *ops)
{
    *ops = (ulph_operators){0};
    fluid_rows_init(&ops->rows);
    ops->max_condition = ULPH_MAX_CONDITION_M;
}

void ulph_operators_free(ulph_operators *ops)
{
    const double max_condition = ops->max_condition;
    fluid_rows_free(&ops->rows);
    free(ops->neighbours);
    free(ops->shape);
    free(ops->shape_inv);
    free(ops->flags);
    free(ops->informative);
    ulph_operators_init(ops);
    ops->max_condition = max_condition;
}

/* Room for n particles; 0, or -1 when memory runs out. */
static int reserve_points(ulph_operators *ops, int n)
{
    if (ops->shape && n <= ops->point_capacity)
        return 0;
    const size_t cap = fsi_grown_capacity((size_t)n);
    int failed = 0;
    ops->neighbours = fsi_grow(ops->neighbours, cap * sizeof *ops->neighbours, &failed);
    ops->informative = fsi_grow(ops->informative, cap * sizeof *ops->informative, &failed);
    ops->shape = fsi_grow(ops->shape, cap * FSI_MAT_SIZE * sizeof *ops->shape, &failed);
    ops->shape_inv = fsi_grow(ops->shape_inv, cap * FSI_MAT_SIZE * sizeof *ops->shape_inv,
                              &failed);
    ops->flags = fsi_grow(ops->flags, cap * sizeof *ops->flags, &failed);
    if (failed)
        return -1;
    ops->point_capacity = (int)cap;
    return 0;
}

void ulph_for_blocks(const ulph_operators *ops, void (*block)(void *context, int lo, int hi),
                     void *context)
{
    const fluid_rows *r = &ops->rows;
    const int parallel = ops->n >= FLUID_PARALLEL_MIN_PARTICLES;
    for (int parity = 0; parity < 2; parity++) {
#pragma omp parallel for schedule(dynamic, 1) if (parallel)
        for (int b = parity; b < r->n_blocks; b += 2)
            block(context, r->block_start[b], r->block_start[b + 1]);
    }
}

/* ---- the update ------------------------------------------------------------------ */

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

typedef struct {
    ulph_operators *ops;
    const fluid_particles *p;
} shape_context;

/* Whether a pair informs M (000 Eq. 15): a weight w V > 0 at a non-zero distance. */
static inline int informs(double wv, double r2)
{
    return wv > 0.0 && r2 > 0.0;
}

/* The pairs of the particles of [lo, hi): M's shares w V x_IJ (x) x_IJ (x_JI (x) x_JI is
 * the same), I's sums in registers, J's (a fluid pair) in place. periodic is a constant
 * in each copy the compiler makes. */
static FSI_ALWAYS_INLINE void shape_rows(ulph_operators *ops, const fluid_particles *p, int lo,
                                         int hi, const int periodic)
{
    const fluid_rows *r = &ops->rows;
    const fsi_periodic *per = periodic ? &ops->periodic : NULL;
    const double *restrict x = p->x, *restrict volume = p->volume, *restrict w = r->f;
    const int32_t *restrict pair = r->pair;
    double *restrict shape = ops->shape;
    int32_t *restrict neighbours = ops->neighbours, *restrict informative = ops->informative;
    for (int i = lo; i < hi; i++) {
        double m[FSI_MAT_SIZE] = {0};
        const double vol_i = volume[i];
        int count = 0, useful = 0;
        /* fluid segment: both particles */
        for (int64_t e = r->offset[i]; e < r->fluid_end[i]; e++) {
            double rel[FSI_DIM];
            const int j = pair[e];
            const double r2 = fluid_pair_vector_r2(per, x, i, j, rel);
            const double wv_i = w[e] * volume[j], wv_j = w[e] * vol_i;
            fsi_mat_add_outer(m, wv_i, rel, rel);
            fsi_mat_add_outer(&shape[(size_t)j * FSI_MAT_SIZE], wv_j, rel, rel);
            count++;
            useful += informs(wv_i, r2);
            neighbours[j]++;
            informative[j] += informs(wv_j, r2);
        }
        /* boundary segment (and a wall's or solid particle's own row): I only */
        for (int64_t e = r->split[i]; e < r->boundary_end[i]; e++) {
            double rel[FSI_DIM];
            const int j = pair[e];
            const double r2 = fluid_pair_vector_r2(per, x, i, j, rel);
            const double wv_i = w[e] * volume[j];
            fsi_mat_add_outer(m, wv_i, rel, rel);
            count++;
            useful += informs(wv_i, r2);
        }
        for (int c = 0; c < FSI_MAT_SIZE; c++)
            shape[(size_t)i * FSI_MAT_SIZE + c] += m[c];
        neighbours[i] += count;
        informative[i] += useful;
    }
}

static void shape_block(void *context, int lo, int hi)
{
    const shape_context *c = context;
    if (fsi_periodic_any(&c->ops->periodic))
        shape_rows(c->ops, c->p, lo, hi, 1);
    else
        shape_rows(c->ops, c->p, lo, hi, 0);
}

/* M_I exactly symmetric, its inverse under the rule; returns 1 when i is flagged
 * ULPH_SINGULAR_SHAPE. */
static int shape_finish(ulph_operators *ops, const fluid_verlet *list, int i)
{
    double *m = &ops->shape[(size_t)i * FSI_MAT_SIZE];
    double *m_inv = &ops->shape_inv[(size_t)i * FSI_MAT_SIZE];
    /* Exactly symmetric (w V x_a x_b and w V x_b x_a round differently); the adjugate
     * inverse of a symmetric matrix is then exactly symmetric too. */
    for (int a = 0; a < FSI_DIM; a++)
        for (int b = a + 1; b < FSI_DIM; b++)
            FSI_MAT(m, a, b) = FSI_MAT(m, b, a) = 0.5 * (FSI_MAT(m, a, b) + FSI_MAT(m, b, a));
    if (list->idle[i]) {
        fsi_mat_zero(m_inv);
        ops->flags[i] = ULPH_IDLE_WALL;
        return 0;
    }
    if (ops->informative[i] < FSI_DIM + 1 || shape_inverse(m, m_inv, ops->max_condition) != 0) {
        fsi_mat_zero(m_inv);
        ops->flags[i] = ULPH_SINGULAR_SHAPE;
        return 1;
    }
    ops->flags[i] = 0;
    return 0;
}

int ulph_operators_update_list(ulph_operators *ops, const gaussian_kernel *k,
                               const fluid_verlet *list, const fluid_particles *p,
                               int list_rebuilt)
{
    const int n = p->n;
    fluid_rows *r = &ops->rows;
    ops->n = 0;
    ops->n_pairs = 0;
    ops->n_singular = 0;
    ops->periodic = list->periodic;
    if (list->n != n || n < 0 || reserve_points(ops, n) != 0 ||
        ((list_rebuilt || r->n != n) && fluid_rows_build(r, list, p, 1) != 0)) {
        ulph_operators_free(ops);
        return -1;
    }
    ops->n = n;
    const int parallel = n >= FLUID_PARALLEL_MIN_PARTICLES;
    const fsi_periodic *per = fsi_periodic_any(&ops->periodic) ? &ops->periodic : NULL;
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (parallel)
    for (int i = 0; i < n; i++) {
        fluid_rows_filter_row(r, k->support2, per, p->x, i);
        gaussian_kernel_w2_row(k, r->f + r->offset[i], r->fluid_end[i] - r->offset[i]);
        gaussian_kernel_w2_row(k, r->f + r->split[i], r->boundary_end[i] - r->split[i]);
        fsi_mat_zero(&ops->shape[(size_t)i * FSI_MAT_SIZE]);
        ops->neighbours[i] = ops->informative[i] = 0;
    }
    shape_context c = {ops, p};
    ulph_for_blocks(ops, shape_block, &c);
    int n_singular = 0;
    int64_t n_pairs = 0;
#pragma omp parallel for schedule(dynamic, FLUID_CHUNK) if (parallel) \
    reduction(+ : n_singular, n_pairs)
    for (int i = 0; i < n; i++) {
        n_singular += shape_finish(ops, list, i);
        n_pairs += ops->neighbours[i];
    }
    ops->n_pairs = n_pairs;
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
        rc = ulph_operators_update_list(ops, k, &list, p, 1);
    else
        ulph_operators_free(ops);
    fluid_verlet_free(&list);
    return rc;
}

/* ---- the operators --------------------------------------------------------------- */

/* The sums of the operators without M^-1, per pair (fluid pairs to both particles):
 * raw[i] of grad f, B_I of L, or (div) directly with M^-1 applied per side. */
typedef struct {
    const ulph_operators *ops;
    const fluid_particles *p;
    const double *field;        /* f[n] or u[n * FSI_DIM] */
    double *out;
    int kind;                   /* OP_GRADIENT, OP_VECTOR_GRADIENT (B), OP_DIVERGENCE */
} operator_context;

enum { OP_GRADIENT, OP_VECTOR_GRADIENT, OP_DIVERGENCE };

/* One side's share: I at rel (x_IJ as I sees it) with wv = w V_J and A(f) = f_J - f_I. */
static inline void operator_add(const operator_context *c, int i, double wv, const double *rel,
                                const double *delta)
{
    switch (c->kind) {
    case OP_GRADIENT:
        for (int a = 0; a < FSI_DIM; a++)
            c->out[(size_t)i * FSI_DIM + a] += wv * delta[0] * rel[a];
        break;
    case OP_VECTOR_GRADIENT:
        fsi_mat_add_outer(&c->out[(size_t)i * FSI_MAT_SIZE], wv, delta, rel);
        break;
    default: {
        double y[FSI_DIM], s = 0.0;
        fsi_mat_vec(&c->ops->shape_inv[(size_t)i * FSI_MAT_SIZE], rel, y);
        for (int a = 0; a < FSI_DIM; a++)
            s += delta[a] * y[a];
        c->out[i] += wv * s;
    }
    }
}

/* The pair of entry e of I's row; both: a fluid pair, added to J too (x_JI = -x_IJ and
 * A_J(f) = -A_I(f): their product is the same). */
static inline void operator_pair(const operator_context *c, int i, int64_t e, int both)
{
    const fluid_rows *r = &c->ops->rows;
    const double *field = c->field, *volume = c->p->volume;
    const int width = c->kind == OP_GRADIENT ? 1 : FSI_DIM;
    const int j = r->pair[e];
    double rel[FSI_DIM], delta[FSI_DIM];
    ulph_pair_vector(c->ops, c->p->x, i, j, rel);
    for (int a = 0; a < width; a++)
        delta[a] = field[(size_t)j * width + a] - field[(size_t)i * width + a];
    operator_add(c, i, r->f[e] * volume[j], rel, delta);
    if (both)
        operator_add(c, j, r->f[e] * volume[i], rel, delta);
}

static void operator_block(void *context, int lo, int hi)
{
    const operator_context *c = context;
    const fluid_rows *r = &c->ops->rows;
    for (int i = lo; i < hi; i++) {
        for (int64_t e = r->offset[i]; e < r->fluid_end[i]; e++)
            operator_pair(c, i, e, 1);
        for (int64_t e = r->split[i]; e < r->boundary_end[i]; e++)
            operator_pair(c, i, e, 0);
    }
}

/* The operator's sums into out (zeroed first), then M^-1 applied per particle. */
static void apply(const ulph_operators *ops, const fluid_particles *p, const double *field,
                  double *out, int kind)
{
    const int n = ops->n;
    const size_t width = kind == OP_GRADIENT ? FSI_DIM : kind == OP_VECTOR_GRADIENT
                                                             ? FSI_MAT_SIZE : 1;
    memset(out, 0, (size_t)n * width * sizeof *out);
    operator_context c = {ops, p, field, out, kind};
    ulph_for_blocks(ops, operator_block, &c);
    if (kind == OP_DIVERGENCE)
        return;
#pragma omp parallel for schedule(static) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        const double *m_inv = &ops->shape_inv[(size_t)i * FSI_MAT_SIZE];
        double *o = &out[(size_t)i * width];
        if (kind == OP_GRADIENT) {
            double raw[FSI_DIM];
            memcpy(raw, o, sizeof raw);
            fsi_mat_vec(m_inv, raw, o);
        } else {
            double b[FSI_MAT_SIZE];
            memcpy(b, o, sizeof b);
            fsi_mat_mul(b, m_inv, o); /* L = B M^-1 (M^-1 symmetric) */
        }
    }
}

void ulph_gradient_scalar(const ulph_operators *ops, const fluid_particles *p, const double *f,
                          double *grad)
{
    apply(ops, p, f, grad, OP_GRADIENT);
}

void ulph_gradient_vector(const ulph_operators *ops, const fluid_particles *p, const double *u,
                          double *grad)
{
    apply(ops, p, u, grad, OP_VECTOR_GRADIENT);
}

void ulph_divergence(const ulph_operators *ops, const fluid_particles *p, const double *u,
                     double *div)
{
    apply(ops, p, u, div, OP_DIVERGENCE);
}
