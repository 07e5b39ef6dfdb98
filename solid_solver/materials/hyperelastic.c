/* Total-form stress of the deformation gradient (material_total_stress, material.h):
 * Saint Venant-Kirchhoff and compressible neo-Hookean hyperelasticity, and the
 * Almansi-Hooke law 003 uses in its TLSPH solid for linear_elastic. The equations, the
 * 2D idealisations and the tests are in docs/materials.md, "Hyperelastic materials".
 *
 * 2D builds: F is the in-plane block and F_zz = lz, a principal stretch (the
 * out-of-plane shears vanish in plane strain and plane stress alike), so every tensor
 * below is block diagonal: an FSI_DIM block (core/small_tensor.h) and a zz scalar.
 * In 3D builds lz = 1 and the zz scalars (E_zz, e_zz, lz^2 - 1) are 0 identically:
 * the same formulas hold with the block the whole tensor.
 *
 * Every strain is formed from the displacement gradient H = F - I (and from
 * I - F^-1 = H F^-1), not as F^T F - I: near F = I the latter loses the digits of the
 * strain to cancellation (a relative 1e-16 / |eps|). */
#include <float.h>
#include <math.h>

#include "material.h"
#include "small_tensor.h"

/* F^-1 of the neo-Hookean and Almansi-Hooke laws is refused beyond this Frobenius
 * condition number: principal stretches 1e12 apart are no continuum, and
 * fsi_mat_inverse's own check would fail a little further on. */
#define MAX_CONDITION_F 1e12

/* Newton iterations for the neo-Hookean thickness stretch: from the start below the
 * convergence is monotone and quadratic (at most 6 iterations for an in-plane det F
 * between 0.25 and 2.25); det F = 1e-20 at nu = 0.499 takes 88, most of them in the
 * initial, linear phase. */
#define NEWTON_MAX_ITERATIONS 200

typedef struct {
    double f[FSI_MAT_SIZE];     /* F (the in-plane block in 2D) */
    double h[FSI_MAT_SIZE];     /* H = F - I */
    double det;                 /* det of the block, > 0 */
    double lz;                  /* F_zz: solved in plane stress, else 1 */
} kinematics;

typedef struct {
    double p[FSI_MAT_SIZE];     /* P, the block (P_zz is not reported) */
    double s[FSI_MAT_SIZE];     /* Cauchy stress, the block */
    double s_zz;                /* sigma_zz (2D) */
    double w;                   /* W per reference volume */
} response;

static int plane_stress(const material *m)
{
#if FSI_DIM == 2
    return m->plane == MATERIAL_PLANE_STRESS;
#else
    (void)m;
    return 0;
#endif
}

/* G = I - F^-1 = H F^-1, and F^-1 (-1 when F is numerically singular). */
static int inverse_parts(const kinematics *k, double *f_inv, double *g)
{
    if (fsi_mat_inverse(k->f, f_inv, MAX_CONDITION_F) != 0)
        return -1;
    fsi_mat_mul(k->h, f_inv, g);
    return 0;
}

/* out = (a + a^T + c) / 2 (the strains E and e below, c the quadratic part). */
static void half_sym_plus(const double *a, const double *c, double *out)
{
    for (int i = 0; i < FSI_DIM; i++)
        for (int j = 0; j < FSI_DIM; j++)
            FSI_MAT(out, i, j) = 0.5 * (FSI_MAT(a, i, j) + FSI_MAT(a, j, i) + FSI_MAT(c, i, j));
}

/* t = lambda tr I + 2 mu e on the block; the zz component is returned. Hooke's law of
 * the strain (e, e_zz) whose full trace is tr. */
static double hooke_block(const material *m, const double *e, double e_zz, double tr,
                          double *t)
{
    const double lam = m->lame_lambda, two_mu = 2.0 * m->shear_modulus;
    for (int i = 0; i < FSI_DIM; i++)
        for (int j = 0; j < FSI_DIM; j++)
            FSI_MAT(t, i, j) = two_mu * FSI_MAT(e, i, j) + (i == j ? lam * tr : 0.0);
    return lam * tr + two_mu * e_zz;
}

/* lambda/2 tr^2 + mu e:e, the energy density of Hooke's law at the strain (e, e_zz). */
static double hooke_energy(const material *m, const double *e, double e_zz, double tr)
{
    return 0.5 * m->lame_lambda * tr * tr +
           m->shear_modulus * (fsi_mat_ddot(e, e) + e_zz * e_zz);
}

/* The zz strain that makes Hooke's zz stress vanish: lambda (tr_in + x) + 2 mu x = 0,
 * x = -lambda tr_in / (lambda + 2 mu) = -nu / (1 - nu) tr_in. */
static double plane_stress_zz(const material *m, double tr_in)
{
    return -m->lame_lambda * tr_in / (m->lame_lambda + 2.0 * m->shear_modulus);
}

/* Saint Venant-Kirchhoff: S = D : E of the Green-Lagrange strain
 * E = (F^T F - I) / 2 = (H + H^T + H^T H) / 2, P = F S, sigma = F S F^T / J. Plane
 * stress: S_zz = 0 gives E_zz = (lz^2 - 1) / 2 in closed form (plane_stress_zz),
 * real only while 1 + 2 E_zz > 0. */
static int saint_venant_kirchhoff(const material *m, kinematics *k, response *r)
{
    double hth[FSI_MAT_SIZE], e[FSI_MAT_SIZE], s[FSI_MAT_SIZE], pft[FSI_MAT_SIZE];
    fsi_mat_transpose_mul(k->h, k->h, hth);
    half_sym_plus(k->h, hth, e);
    double e_zz = 0.0;
    if (plane_stress(m)) {
        e_zz = plane_stress_zz(m, fsi_mat_trace(e));
        if (!(1.0 + 2.0 * e_zz > 0.0))
            return -1;
        k->lz = sqrt(1.0 + 2.0 * e_zz);
    }
    const double tr = fsi_mat_trace(e) + e_zz;
    const double s_zz = hooke_block(m, e, e_zz, tr, s);
    fsi_mat_mul(k->f, s, r->p);
    const double j = k->det * k->lz;
    fsi_mat_mul_transpose(r->p, k->f, pft);
    for (int q = 0; q < FSI_MAT_SIZE; q++)
        r->s[q] = pft[q] / j;
    r->s_zz = k->lz * k->lz * s_zz / j;
    r->w = hooke_energy(m, e, e_zz, tr);
    return 0;
}

/* Plane-stress thickness of the neo-Hookean solid. With s = ln lz and J = det lz,
 * J sigma_zz = mu (lz^2 - 1) + lambda ln J, so the root of
 *     h(s) = mu (e^(2s) - 1) + lambda (ln det + s)
 * is wanted. h is increasing and convex (h' = 2 mu e^(2s) + lambda > 0, h'' > 0), so
 * it has one root, and at the root of its linearisation about s = 0,
 * s0 = -lambda ln det / (2 mu + lambda), h(s0) = mu (e^(2 s0) - 1 - 2 s0) >= 0: Newton
 * from s0 stays right of the root and decreases monotonically to it, with no
 * overshoot (the guard is the iteration cap and the finiteness of every step). */
static int neo_hookean_thickness(const material *m, double log_det, double *s_out)
{
    const double mu = m->shear_modulus, lam = m->lame_lambda;
    double s = -lam * log_det / (2.0 * mu + lam);
    for (int it = 0; it < NEWTON_MAX_ITERATIONS; it++) {
        const double step = (mu * expm1(2.0 * s) + lam * (log_det + s)) /
                            (2.0 * mu * exp(2.0 * s) + lam);
        if (!isfinite(step))
            return -1;
        s -= step;
        if (fabs(step) <= 4.0 * DBL_EPSILON * fmax(1.0, fabs(s))) {
            *s_out = s;
            return 0;
        }
    }
    return -1;
}

/* Compressible neo-Hookean (Bonet & Wood 2008, Sec. 6.4.3; often attributed to
 * Ciarlet 1988):
 *   W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2,
 *   P = mu (F - F^-T) + lambda ln J F^-T,   sigma = (mu (b - I) + lambda ln J I) / J,
 * with F - F^-T = H + G^T, b - I = H + H^T + H H^T, I1 - 3 = 2 tr H + H:H + lz^2 - 1. */
static int neo_hookean(const material *m, kinematics *k, response *r)
{
    const double mu = m->shear_modulus, lam = m->lame_lambda;
    double f_inv[FSI_MAT_SIZE], g[FSI_MAT_SIZE], hht[FSI_MAT_SIZE];
    if (inverse_parts(k, f_inv, g) != 0)
        return -1;
    const double log_det = log(k->det);
    double s = 0.0;                                 /* ln lz */
    if (plane_stress(m)) {
        if (neo_hookean_thickness(m, log_det, &s) != 0)
            return -1;
        k->lz = exp(s);
    }
    const double log_j = log_det + s, j = k->det * k->lz;
    const double lz2_minus_1 = expm1(2.0 * s);
    fsi_mat_mul_transpose(k->h, k->h, hht);
    for (int a = 0; a < FSI_DIM; a++)
        for (int b = 0; b < FSI_DIM; b++) {
            FSI_MAT(r->p, a, b) = mu * (FSI_MAT(k->h, a, b) + FSI_MAT(g, b, a)) +
                                  lam * log_j * FSI_MAT(f_inv, b, a);
            const double b_minus_i =
                FSI_MAT(k->h, a, b) + FSI_MAT(k->h, b, a) + FSI_MAT(hht, a, b);
            FSI_MAT(r->s, a, b) = (mu * b_minus_i + (a == b ? lam * log_j : 0.0)) / j;
        }
    r->s_zz = (mu * lz2_minus_1 + lam * log_j) / j;
    const double i1_minus_3 =
        2.0 * fsi_mat_trace(k->h) + fsi_mat_ddot(k->h, k->h) + lz2_minus_1;
    r->w = 0.5 * mu * i1_minus_3 - mu * log_j + 0.5 * lam * log_j * log_j;
    return 0;
}

/* 003's TLSPH law: Hooke's law of the Almansi strain
 *   e = (I - F^-T F^-1) / 2 = (G + G^T - G^T G) / 2,   G = I - F^-1,
 * sigma = lambda tr(e) I + 2 mu e, P = J sigma F^-T. Cauchy-elastic, not hyperelastic:
 * W = J (lambda/2 tr(e)^2 + mu e:e) is the small-strain energy 1/2 eps : D : eps
 * (e = eps + O(eps^2), J = 1 + O(eps)) up to O(eps^3), so dW/dF = P + O(eps^2): exact
 * to second order in the strain, and the energy check of a run at small strain holds
 * to that order. Plane stress: sigma_zz = 0 gives e_zz = (1 - lz^-2) / 2 in closed
 * form (plane_stress_zz), real only while 1 - 2 e_zz > 0. */
static int almansi_hooke(const material *m, kinematics *k, response *r)
{
    double f_inv[FSI_MAT_SIZE], g[FSI_MAT_SIZE], gtg[FSI_MAT_SIZE], e[FSI_MAT_SIZE];
    if (inverse_parts(k, f_inv, g) != 0)
        return -1;
    fsi_mat_transpose_mul(g, g, gtg);
    fsi_mat_scale(gtg, -1.0);
    half_sym_plus(g, gtg, e);
    double e_zz = 0.0;
    if (plane_stress(m)) {
        e_zz = plane_stress_zz(m, fsi_mat_trace(e));
        if (!(1.0 - 2.0 * e_zz > 0.0))
            return -1;
        k->lz = 1.0 / sqrt(1.0 - 2.0 * e_zz);
    }
    const double tr = fsi_mat_trace(e) + e_zz, j = k->det * k->lz;
    r->s_zz = hooke_block(m, e, e_zz, tr, r->s);
    fsi_mat_mul_transpose(r->s, f_inv, r->p);      /* sigma F^-T */
    fsi_mat_scale(r->p, j);
    r->w = j * hooke_energy(m, e, e_zz, tr);
    return 0;
}

int material_is_hyperelastic(const material *m)
{
    return m->kind == MATERIAL_SAINT_VENANT_KIRCHHOFF || m->kind == MATERIAL_NEO_HOOKEAN;
}

static int response_finite(const response *r)
{
    for (int q = 0; q < FSI_MAT_SIZE; q++)
        if (!isfinite(r->p[q]) || !isfinite(r->s[q]))
            return 0;
    return isfinite(r->s_zz) && isfinite(r->w);
}

int material_total_stress(const material *m, const double *f, double *p, double sigma[6],
                          double *energy, double *thickness_stretch)
{
    kinematics k;
    for (int i = 0; i < FSI_DIM; i++)
        for (int j = 0; j < FSI_DIM; j++) {
            const double v = FSI_MAT(f, i, j);
            if (!isfinite(v))
                return -1;
            FSI_MAT(k.f, i, j) = v;
            FSI_MAT(k.h, i, j) = v - (i == j ? 1.0 : 0.0);
        }
    k.det = fsi_mat_det(k.f);
    k.lz = 1.0;
    if (!(k.det > 0.0))
        return -1;
    response r;
    int rc;
    switch (m->kind) {
    case MATERIAL_SAINT_VENANT_KIRCHHOFF:
        rc = saint_venant_kirchhoff(m, &k, &r);
        break;
    case MATERIAL_NEO_HOOKEAN:
        rc = neo_hookean(m, &k, &r);
        break;
    case MATERIAL_LINEAR_ELASTIC:
        rc = almansi_hooke(m, &k, &r);
        break;
    case MATERIAL_DRUCKER_PRAGER:
    default:
        rc = -1;        /* plasticity has no total form */
        break;
    }
    if (rc != 0 || !(k.lz > 0.0) || !(k.det * k.lz > 0.0) || !response_finite(&r))
        return -1;

    fsi_mat_copy(r.p, p);
    if (sigma) {
        fsi_mat_to_sym6(r.s, sigma);
#if FSI_DIM == 2
        sigma[2] = r.s_zz;
        sigma[4] = sigma[5] = 0.0;
#endif
    }
    if (energy)
        *energy = r.w;
    if (thickness_stretch)
        *thickness_stretch = k.lz;
    return 0;
}
