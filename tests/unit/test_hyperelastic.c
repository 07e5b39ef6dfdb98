/* Unit test of the total-form materials (material_total_stress, materials/
 * hyperelastic.c): Saint Venant-Kirchhoff, compressible neo-Hookean and the
 * Almansi-Hooke law of linear_elastic, in plane strain and plane stress (2D builds;
 * 3D builds run the one 3D case). Every expected value is the test's own: finite
 * differences of W, rotations, Hooke's law written with E and nu, closed forms of
 * uniaxial stretch.
 *
 *  (a) P = dW/dF by central differences at random finite F (hyperelastic laws), and
 *      to first order in the strain for the Almansi-Hooke law (not hyperelastic);
 *  (b) objectivity: P(QF) = Q P(F), sigma(QF) = Q sigma Q^T, W(QF) = W(F), same F_zz;
 *  (c) F = I: no stress, no energy, F_zz = 1, exactly;
 *  (d) small strains: Hooke's law (plane strain: sigma_xx = (lambda + 2 mu) eps for a
 *      uniaxial strain, ...; plane stress: E / (1 - nu^2) (eps_xx + nu eps_yy) and
 *      F_zz - 1 = -nu / (1 - nu) tr eps) to O(eps^2), and W = sigma : eps / 2;
 *  (e) sigma = P F^T / J (J with F_zz) and symmetric;
 *  (f) plane stress: sigma_zz = 0 to round-off, and the test's own zz stress of the
 *      returned F_zz vanishes;
 *  (g) uniaxial stretch against the closed forms (neo-Hookean; SVK too, with its
 *      softening in compression); the Almansi-Hooke law at finite strain against its
 *      definition (its P = dW/dF is only first-order, so (a) cannot pin its W);
 *  (h) -1 and nothing written for det F <= 0, non-finite F, Drucker-Prager, and a
 *      plane-stress state without a thickness stretch; material_update's NaN for the
 *      hyperelastic kinds; material_is_hyperelastic, material_kind_name.
 * Each tolerance is derived where it is defined. Exit 0 = pass. */
#include "dim.h"
#include "material.h"
#include "small_tensor.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "unit_check.h"
#include "unit_material.h"
#include "unit_random.h"

/* Round-off tolerance of one evaluation, relative to the size of the quantity: a few
 * dozen operations on numbers of one scale (strains of 0.1-0.3 formed from H = F - I,
 * the Newton solve of the neo-Hookean F_zz converged to 4 ulp) give errors of a few
 * 1e-16; 1e-12 leaves room for rotated inputs (entries of size 1 carrying a strain of
 * size 0.1 lose one digit) while a modelling error (a wrong factor, a missing term)
 * is of the size of the strain, 1e-1. */
#define ROUND_OFF 1e-12

/* Central differences of W with step h = 1e-5 on entries of size 1: truncation
 * h^2 / 6 |W'''| ~ 2e-11 M, cancellation 1e-16 |W| / h ~ 1e-12 M, against |P| ~ 0.1 M
 * (M the P-wave modulus): a relative 1e-9 expected, 1e-6 allowed. */
#define FD_STEP 1e-5
#define FD_TOL 1e-6

static const double E_MOD = 2.0e6, NU = 0.4;   /* lambda = 4 mu: the two terms differ */

static const material_kind LAWS[] = {MATERIAL_SAINT_VENANT_KIRCHHOFF, MATERIAL_NEO_HOOKEAN,
                                     MATERIAL_LINEAR_ELASTIC};
#define N_LAWS 3
#if FSI_DIM == 2
static const material_plane PLANES[] = {MATERIAL_PLANE_STRAIN, MATERIAL_PLANE_STRESS};
#define N_PLANES 2
#else
static const material_plane PLANES[] = {MATERIAL_PLANE_STRAIN};   /* ignored in 3D */
#define N_PLANES 1
#endif

static material make(material_kind kind, material_plane plane)
{
    return unit_material(kind, plane, E_MOD, NU);
}

static const char *label(const material *m)
{
    static char text[96];
    snprintf(text, sizeof text, "%s, %s", material_kind_name(m->kind),
             FSI_DIM == 3 ? "3D" : (m->plane == MATERIAL_PLANE_STRESS ? "plane stress"
                                                                        : "plane strain"));
    return text;
}

/* Everything material_total_stress returns, and its return code. */
typedef struct {
    int rc;
    double p[FSI_MAT_SIZE], sigma[6], w, lz;
} result;

static result eval(const material *m, const double *f)
{
    result r;
    memset(&r, 0, sizeof r);
    r.rc = material_total_stress(m, f, r.p, r.sigma, &r.w, &r.lz);
    return r;
}

static double sym6_max(const double s[6])
{
    double v = 0.0;
    for (int k = 0; k < 6; k++)
        v = fmax(v, fabs(s[k]));
    return v;
}

/* A rotation by angle about axis (in 2D about z; the axis is ignored). */
static void rotation(double angle, const double axis[3], double *q)
{
    const double c = cos(angle), s = sin(angle);
#if FSI_DIM == 2
    (void)axis;
    q[0] = c;
    q[1] = -s;
    q[2] = s;
    q[3] = c;
#else
    const double n = sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    const double u[3] = {axis[0] / n, axis[1] / n, axis[2] / n};
    /* Rodrigues: Q = c I + s [u]x + (1 - c) u u^T */
    const double ux[3][3] = {{0, -u[2], u[1]}, {u[2], 0, -u[0]}, {-u[1], u[0], 0}};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            FSI_MAT(q, i, j) = (i == j ? c : 0.0) + s * ux[i][j] + (1.0 - c) * u[i] * u[j];
#endif
}

static void random_rotation(double *q)
{
    const double axis[3] = {uniform() - 0.5, uniform() - 0.5, uniform() - 0.5 + 1e-3};
    rotation(2.0 * M_PI * uniform(), axis, q);
}

/* F = Q (I + a A), A with entries uniform in [-1, 1], det F >= 0.2 (redrawn). */
static void random_f(double a, double *f)
{
    double q[FSI_MAT_SIZE], u[FSI_MAT_SIZE];
    do {
        random_rotation(q);
        fsi_mat_identity(u);
        for (int k = 0; k < FSI_MAT_SIZE; k++)
            u[k] += a * (2.0 * uniform() - 1.0);
        fsi_mat_mul(q, u, f);
    } while (!(fsi_mat_det(f) >= 0.2));
}

/* Size a of the random finite deformations: 0.3 (principal stretches about 0.5 to
 * 1.6); 0.15 for the Almansi-Hooke law, whose plane stress has no thickness stretch
 * once the in-plane tr e < -(1 - nu) / (2 nu) = -0.75 here (a biaxial compression
 * to 0.76, within reach of a = 0.3). */
static double finite_amplitude(material_kind kind)
{
    return kind == MATERIAL_LINEAR_ELASTIC ? 0.15 : 0.3;
}

/* |dW/dF - P| / |P| (Frobenius) by central differences with step h. */
static double fd_mismatch(const material *m, const double *f, double h)
{
    const result r0 = eval(m, f);
    if (r0.rc != 0)
        return INFINITY;
    double diff[FSI_MAT_SIZE];
    for (int k = 0; k < FSI_MAT_SIZE; k++) {
        double fp[FSI_MAT_SIZE], fm[FSI_MAT_SIZE];
        fsi_mat_copy(f, fp);
        fsi_mat_copy(f, fm);
        fp[k] += h;
        fm[k] -= h;
        const result rp = eval(m, fp), rm = eval(m, fm);
        if (rp.rc != 0 || rm.rc != 0)
            return INFINITY;
        diff[k] = (rp.w - rm.w) / (2.0 * h) - r0.p[k];
    }
    return fsi_mat_norm(diff) / fsi_mat_norm(r0.p);
}

/* (a) P = dW/dF. */
static void test_derivative(void)
{
    for (int l = 0; l < N_LAWS; l++)
        for (int pl = 0; pl < N_PLANES; pl++) {
            const material m = make(LAWS[l], PLANES[pl]);
            for (int trial = 0; trial < 8; trial++) {
                double f[FSI_MAT_SIZE];
                if (LAWS[l] != MATERIAL_LINEAR_ELASTIC) {
                    random_f(0.3, f);
                    const double mis = fd_mismatch(&m, f, FD_STEP);
                    CHECK(mis <= FD_TOL, "%s: |dW/dF - P| / |P| = %.3g at det F = %.3f (trial %d)",
                          label(&m), mis, fsi_mat_det(f), trial);
                } else {
                    /* Not hyperelastic: P - dW/dF = O(M eps^2) against |P| = O(M eps), so
                     * the relative mismatch is of the order of the strain, eps ~ a |A| with
                     * |A| up to FSI_DIM (measured up to 2.8 a over these and more draws);
                     * allowed 10 a at a = 1e-3 and at 1e-4, so it must shrink with the
                     * strain. Step 1e-7: truncation h^2 |W'''| ~ 1e-14 M and cancellation
                     * ~1e-13 M against |P| ~ 1e-4 M. */
                    const double amp[2] = {1e-3, 1e-4};
                    for (int s = 0; s < 2; s++) {
                        random_f(amp[s], f);
                        const double mis = fd_mismatch(&m, f, 1e-7);
                        CHECK(mis <= 10.0 * amp[s],
                              "%s: |dW/dF - P| / |P| = %.3g at strain %g (trial %d)", label(&m),
                              mis, amp[s], trial);
                    }
                }
            }
        }
}

/* (b) Objectivity. */
static void test_objectivity(void)
{
    for (int l = 0; l < N_LAWS; l++)
        for (int pl = 0; pl < N_PLANES; pl++) {
            const material m = make(LAWS[l], PLANES[pl]);
            for (int trial = 0; trial < 8; trial++) {
                double f[FSI_MAT_SIZE], q[FSI_MAT_SIZE], qf[FSI_MAT_SIZE], qp[FSI_MAT_SIZE];
                random_f(finite_amplitude(LAWS[l]), f);
                random_rotation(q);
                fsi_mat_mul(q, f, qf);
                const result a = eval(&m, f), b = eval(&m, qf);
                CHECK(a.rc == 0 && b.rc == 0, "%s: objectivity evaluations failed", label(&m));
                fsi_mat_mul(q, a.p, qp);
                double d[FSI_MAT_SIZE];
                fsi_mat_axpy(b.p, -1.0, qp, d);
                CHECK(fsi_mat_norm(d) <= ROUND_OFF * fsi_mat_norm(a.p),
                      "%s: |P(QF) - Q P(F)| = %.3g of |P| = %.3g", label(&m), fsi_mat_norm(d),
                      fsi_mat_norm(a.p));
                CHECK(fabs(b.w - a.w) <= ROUND_OFF * fabs(a.w), "%s: W(QF) = %.17g, W(F) = %.17g",
                      label(&m), b.w, a.w);
                double rs[6];
                memcpy(rs, a.sigma, sizeof rs);
                fsi_sym6_rotate(q, rs);
                double worst = 0.0;
                for (int k = 0; k < 6; k++)
                    worst = fmax(worst, fabs(rs[k] - b.sigma[k]));
                CHECK(worst <= ROUND_OFF * sym6_max(a.sigma),
                      "%s: |sigma(QF) - Q sigma Q^T| = %.3g", label(&m), worst);
                CHECK(fabs(a.lz - b.lz) <= ROUND_OFF, "%s: F_zz %.17g and %.17g", label(&m), a.lz,
                      b.lz);
            }
        }
}

/* (c) The reference state is stress- and energy-free, exactly. */
static void test_reference_state(void)
{
    for (int l = 0; l < N_LAWS; l++)
        for (int pl = 0; pl < N_PLANES; pl++) {
            const material m = make(LAWS[l], PLANES[pl]);
            double f[FSI_MAT_SIZE];
            fsi_mat_identity(f);
            const result r = eval(&m, f);
            CHECK(r.rc == 0 && fsi_mat_norm(r.p) == 0.0 && sym6_max(r.sigma) == 0.0 &&
                      r.w == 0.0 && r.lz == 1.0,
                  "%s: at F = I: rc %d, |P| %g, |sigma| %g, W %g, F_zz %.17g", label(&m), r.rc,
                  fsi_mat_norm(r.p), sym6_max(r.sigma), r.w, r.lz);
        }
}

/* Hooke's law written with E and nu for an in-plane (or 3D) strain eps: plane strain
 * and 3D sigma = E / (1 + nu) (eps + nu / (1 - 2 nu) tr eps I) (sigma_zz in 2D from
 * eps_zz = 0); plane stress sigma = E / (1 - nu^2) ((1 - nu) eps + nu tr eps I) in the
 * plane, sigma_zz = 0. */
static void hooke(material_plane plane, const double *eps, double s[6])
{
    const double tr = fsi_mat_trace(eps);
    double t[FSI_MAT_SIZE];
    double zz = E_MOD * NU / ((1.0 + NU) * (1.0 - 2.0 * NU)) * tr;
    for (int i = 0; i < FSI_DIM; i++)
        for (int j = 0; j < FSI_DIM; j++) {
            const double e = FSI_MAT(eps, i, j), kd = i == j ? 1.0 : 0.0;
            if (plane == MATERIAL_PLANE_STRESS && FSI_DIM == 2)
                FSI_MAT(t, i, j) = E_MOD / (1.0 - NU * NU) * ((1.0 - NU) * e + NU * tr * kd);
            else
                FSI_MAT(t, i, j) = E_MOD / (1.0 + NU) * (e + NU / (1.0 - 2.0 * NU) * tr * kd);
        }
    for (int k = 0; k < 6; k++)
        s[k] = 0.0;
    fsi_mat_to_sym6(t, s);
#if FSI_DIM == 2
    s[2] = plane == MATERIAL_PLANE_STRESS ? 0.0 : zz;
#else
    (void)zz;
#endif
}

/* (d) Small strains: Hooke's law. */
static void test_small_strain(void)
{
    /* The laws differ from Hooke's law by O(eps^2) terms (the neo-Hookean uniaxial
     * sigma_xx = M eps - (mu + 3 lambda / 2) eps^2 + ..., SVK's (3/2) M eps^2, J and
     * F^-T in P); with eps0 = 1e-4 the bound of every strain component, 200 random
     * strains gave |sigma - Hooke| and |P - Hooke| up to 4.5 M eps0^2 (the Almansi-Hooke
     * law; SVK 3.0, neo-Hookean 3.5), |W - sigma:eps/2| up to 5.8 M eps0^3 and
     * |F_zz - 1 - Hooke's| up to 4.7 eps0^2. Allowed 10 M eps0^2, 20 M eps0^3 and
     * 10 eps0^2: a first-order error (1e-4 M in the stress) fails by three orders of
     * magnitude. */
    const double eps0 = 1e-4;
    for (int l = 0; l < N_LAWS; l++)
        for (int pl = 0; pl < N_PLANES; pl++) {
            const material m = make(LAWS[l], PLANES[pl]);
            const double big_m = m.lame_lambda + 2.0 * m.shear_modulus;
            for (int trial = 0; trial < 6; trial++) {
                double eps[FSI_MAT_SIZE] = {0};
                if (trial == 0) {
                    eps[0] = eps0;            /* uniaxial strain along x */
                } else {
                    for (int i = 0; i < FSI_DIM; i++)
                        for (int j = i; j < FSI_DIM; j++)
                            FSI_MAT(eps, i, j) = FSI_MAT(eps, j, i) =
                                eps0 * (2.0 * uniform() - 1.0);
                }
                double f[FSI_MAT_SIZE], want[6];
                fsi_mat_identity(f);
                for (int k = 0; k < FSI_MAT_SIZE; k++)
                    f[k] += eps[k];
                hooke(PLANES[pl], eps, want);
                const result r = eval(&m, f);
                double worst = 0.0, worst_p = 0.0;
                for (int k = 0; k < 6; k++)
                    worst = fmax(worst, fabs(r.sigma[k] - want[k]));
                double w_want = 0.0;
                for (int i = 0; i < FSI_DIM; i++)
                    for (int j = 0; j < FSI_DIM; j++) {
                        const double sij = want[fsi_voigt_index(i, j)];
                        worst_p = fmax(worst_p, fabs(FSI_MAT(r.p, i, j) - sij));
                        w_want += 0.5 * sij * FSI_MAT(eps, i, j);
                    }
                const double tol = 10.0 * big_m * eps0 * eps0;
                CHECK(r.rc == 0 && worst <= tol && worst_p <= tol,
                      "%s: small strain %d: |sigma - Hooke| = %.3g, |P - Hooke| = %.3g, allowed "
                      "%.3g (Hooke's largest %.3g)",
                      label(&m), trial, worst, worst_p, tol, sym6_max(want));
                /* W = sigma : eps / 2 + O(M eps^3). */
                CHECK(fabs(r.w - w_want) <= 20.0 * big_m * eps0 * eps0 * eps0,
                      "%s: small strain %d: W = %.17g, Hooke %.17g", label(&m), trial, r.w,
                      w_want);
                if (FSI_DIM == 2 && PLANES[pl] == MATERIAL_PLANE_STRESS) {
                    const double lz = -NU / (1.0 - NU) * fsi_mat_trace(eps);
                    CHECK(fabs(r.lz - 1.0 - lz) <= 10.0 * eps0 * eps0,
                          "%s: F_zz - 1 = %.6g, -nu/(1-nu) tr eps = %.6g", label(&m), r.lz - 1.0,
                          lz);
                } else {
                    CHECK(r.lz == 1.0, "%s: F_zz = %.17g, expected 1", label(&m), r.lz);
                }
            }
        }
}

/* (e) sigma = P F^T / J, symmetric; (f) plane stress sigma_zz = 0. */
static void test_cauchy_and_plane_stress(void)
{
    for (int l = 0; l < N_LAWS; l++)
        for (int pl = 0; pl < N_PLANES; pl++) {
            const material m = make(LAWS[l], PLANES[pl]);
            for (int trial = 0; trial < 8; trial++) {
                double f[FSI_MAT_SIZE], pft[FSI_MAT_SIZE];
                random_f(finite_amplitude(LAWS[l]), f);
                const result r = eval(&m, f);
                CHECK(r.rc == 0, "%s: evaluation failed at det F = %g", label(&m),
                      fsi_mat_det(f));
                const double j = fsi_mat_det(f) * r.lz, scale = sym6_max(r.sigma);
                fsi_mat_mul_transpose(r.p, f, pft);
                double asym = 0.0, off = 0.0;
                for (int a = 0; a < FSI_DIM; a++)
                    for (int b = 0; b < FSI_DIM; b++) {
                        asym = fmax(asym, fabs(FSI_MAT(pft, a, b) - FSI_MAT(pft, b, a)) / j);
                        off = fmax(off,
                                   fabs(FSI_MAT(pft, a, b) / j - r.sigma[fsi_voigt_index(a, b)]));
                    }
                CHECK(asym <= ROUND_OFF * scale && off <= ROUND_OFF * scale,
                      "%s: P F^T / J asymmetric by %.3g, differs from sigma by %.3g (|sigma| %.3g)",
                      label(&m), asym, off, scale);
#if FSI_DIM == 2
                CHECK(r.sigma[4] == 0.0 && r.sigma[5] == 0.0, "%s: out-of-plane shear %g %g",
                      label(&m), r.sigma[4], r.sigma[5]);
                if (PLANES[pl] != MATERIAL_PLANE_STRESS)
                    continue;
                CHECK(fabs(r.sigma[2]) <= ROUND_OFF * scale, "%s: plane stress sigma_zz = %.3g",
                      label(&m), r.sigma[2]);
                /* The test's own zz stress of the returned F_zz (times J, and for SVK the
                 * second Piola-Kirchhoff S_zz): it vanishes only for the right F_zz. */
                const double lam = m.lame_lambda, mu = m.shear_modulus;
                double c[FSI_MAT_SIZE], binv[FSI_MAT_SIZE], finv[FSI_MAT_SIZE];
                fsi_mat_transpose_mul(f, f, c);
                const double lz2 = r.lz * r.lz;
                double zz = NAN;
                if (LAWS[l] == MATERIAL_SAINT_VENANT_KIRCHHOFF) {
                    const double tr_e = 0.5 * (fsi_mat_trace(c) - 2.0) + 0.5 * (lz2 - 1.0);
                    zz = lam * tr_e + mu * (lz2 - 1.0);
                } else if (LAWS[l] == MATERIAL_NEO_HOOKEAN) {
                    zz = mu * (lz2 - 1.0) + lam * log(j);
                } else {
                    if (fsi_mat_inverse(f, finv, 1e12) != 0) {
                        CHECK(0, "%s: F of det %g not invertible", label(&m), fsi_mat_det(f));
                        continue;
                    }
                    fsi_mat_transpose_mul(finv, finv, binv);
                    const double e_zz = 0.5 * (1.0 - 1.0 / lz2);
                    const double tr_e = 0.5 * (2.0 - fsi_mat_trace(binv)) + e_zz;
                    zz = lam * tr_e + 2.0 * mu * e_zz;
                }
                CHECK(fabs(zz) <= ROUND_OFF * (lam + 2.0 * mu),
                      "%s: the zz stress of F_zz = %.17g is %.3g", label(&m), r.lz, zz);
#endif
            }
        }
}

/* (g) Uniaxial stretch F = diag(l, 1[, 1]) against the closed forms. */
static void test_uniaxial_stretch(void)
{
    static const double stretches[] = {0.3, 0.5, 0.8, 1.25, 2.0, 3.0};
    for (int pl = 0; pl < N_PLANES; pl++) {
        const material nh = make(MATERIAL_NEO_HOOKEAN, PLANES[pl]);
        const material svk = make(MATERIAL_SAINT_VENANT_KIRCHHOFF, PLANES[pl]);
        /* mu and lambda from E and nu, not from material_derive. */
        const double mu = E_MOD / (2.0 * (1.0 + NU)),
                     lam = E_MOD * NU / ((1.0 + NU) * (1.0 - 2.0 * NU));
        for (size_t s = 0; s < sizeof stretches / sizeof stretches[0]; s++) {
            const double l = stretches[s];
            double f[FSI_MAT_SIZE];
            fsi_mat_identity(f);
            f[0] = l;
            const result r = eval(&nh, f);
            double lz = 1.0;
            if (FSI_DIM == 2 && PLANES[pl] == MATERIAL_PLANE_STRESS) {
                /* F_zz has no closed form: mu (lz^2 - 1) + lambda ln(l lz) = 0 is checked
                 * (the Newton residual, relative to lambda + 2 mu), the rest given it. */
                lz = r.lz;
                CHECK(fabs(mu * (lz * lz - 1.0) + lam * log(l * lz)) <= ROUND_OFF * (lam + 2 * mu),
                      "neo_hookean uniaxial %g: F_zz %.17g is not the plane-stress root", l, lz);
            }
            const double lj = log(l * lz), j = l * lz;
            const double pxx = mu * (l - 1.0 / l) + lam * lj / l, pyy = lam * lj;
            const double w = 0.5 * mu * (l * l + lz * lz - 2.0) - mu * lj + 0.5 * lam * lj * lj;
            const double scale = fabs(pxx) + fabs(pyy);
            CHECK(r.rc == 0 && fabs(r.p[0] - pxx) <= ROUND_OFF * scale &&
                      fabs(FSI_MAT(r.p, 1, 1) - pyy) <= ROUND_OFF * scale &&
                      fabs(FSI_MAT(r.p, 0, 1)) + fabs(FSI_MAT(r.p, 1, 0)) <= ROUND_OFF * scale &&
                      fabs(r.w - w) <= ROUND_OFF * fabs(w),
                  "%s uniaxial %g: P_xx %.17g (%.17g), P_yy %.17g (%.17g), W %.17g (%.17g)",
                  label(&nh), l, r.p[0], pxx, FSI_MAT(r.p, 1, 1), pyy, r.w, w);
            /* sigma = P F^T / J; sigma_zz = (mu (lz^2 - 1) + lambda ln J) / J. */
            const double szz = (mu * (lz * lz - 1.0) + lam * lj) / j;
            CHECK(fabs(r.sigma[0] - pxx * l / j) <= ROUND_OFF * scale &&
                      fabs(r.sigma[1] - pyy / j) <= ROUND_OFF * scale &&
                      (FSI_DIM == 3 || fabs(r.sigma[2] - szz) <= ROUND_OFF * scale),
                  "%s uniaxial %g: sigma_xx %.17g, sigma_yy %.17g, sigma_zz %.17g (%.17g)",
                  label(&nh), l, r.sigma[0], r.sigma[1], r.sigma[2], szz);
            if (!(FSI_DIM == 2 && PLANES[pl] == MATERIAL_PLANE_STRESS)) {
                /* SVK in uniaxial strain: E_xx = (l^2 - 1) / 2, P_xx = l M E_xx, the
                 * lateral S = lambda E_xx, so sigma_yy = sigma_zz = lambda E_xx / l. */
                const result q = eval(&svk, f);
                const double exx = 0.5 * (l * l - 1.0), want = l * (lam + 2.0 * mu) * exx;
                const double w_svk = 0.5 * (lam + 2.0 * mu) * exx * exx;
                const double lateral = lam * exx / l;
                CHECK(q.rc == 0 && fabs(q.p[0] - want) <= ROUND_OFF * fabs(want) &&
                          fabs(q.w - w_svk) <= ROUND_OFF * w_svk &&
                          fabs(q.sigma[1] - lateral) <= ROUND_OFF * fabs(want) &&
                          fabs(q.sigma[2] - lateral) <= ROUND_OFF * fabs(want),
                      "%s uniaxial %g: P_xx %.17g (%.17g), W %.17g (%.17g), sigma_yy %.17g, "
                      "sigma_zz %.17g (%.17g)",
                      label(&svk), l, q.p[0], want, q.w, w_svk, q.sigma[1], q.sigma[2],
                      lateral);
            }
        }
        if (!(FSI_DIM == 2 && PLANES[pl] == MATERIAL_PLANE_STRESS)) {
            /* SVK softens in compression (its nominal stress is largest in magnitude at
             * l = 1/sqrt(3) and returns to 0 as l -> 0), neo-Hookean does not. */
            double f[FSI_MAT_SIZE];
            fsi_mat_identity(f);
            double p_svk[2], p_nh[2];
            const double ls[2] = {1.0 / sqrt(3.0), 0.2};
            for (int k = 0; k < 2; k++) {
                f[0] = ls[k];
                p_svk[k] = eval(&svk, f).p[0];
                p_nh[k] = eval(&nh, f).p[0];
            }
            CHECK(p_svk[1] > p_svk[0] && p_nh[1] < p_nh[0],
                  "compression to 0.2 against 1/sqrt(3): SVK P_xx %g -> %g (must soften), NH %g "
                  "-> %g (must stiffen)", p_svk[0], p_svk[1], p_nh[0], p_nh[1]);
        }
    }
}

/* (g) The Almansi-Hooke law at finite strain against its definition, with the test's
 * own strain: e = (I - F^-T F^-1) / 2 (e_zz = (1 - F_zz^-2) / 2), sigma = Hooke's law
 * of e, W = J (lambda/2 tr(e)^2 + mu e:e), J with F_zz. (Its P = dW/dF holds only to
 * first order, so (a) cannot see, e.g., a W without J.) */
static void test_almansi_hooke_definition(void)
{
    const double mu = E_MOD / (2.0 * (1.0 + NU)),
                 lam = E_MOD * NU / ((1.0 + NU) * (1.0 - 2.0 * NU));
    for (int pl = 0; pl < N_PLANES; pl++) {
        const material m = make(MATERIAL_LINEAR_ELASTIC, PLANES[pl]);
        for (int trial = 0; trial < 8; trial++) {
            double f[FSI_MAT_SIZE], finv[FSI_MAT_SIZE], binv[FSI_MAT_SIZE], e[FSI_MAT_SIZE];
            random_f(finite_amplitude(MATERIAL_LINEAR_ELASTIC), f);
            const result r = eval(&m, f);
            if (r.rc != 0 || fsi_mat_inverse(f, finv, 1e12) != 0) {
                CHECK(0, "%s: evaluation failed at det F = %g", label(&m), fsi_mat_det(f));
                continue;
            }
            fsi_mat_transpose_mul(finv, finv, binv);
            fsi_mat_identity(e);
            fsi_mat_axpy(e, -1.0, binv, e);
            fsi_mat_scale(e, 0.5);
            const double e_zz = FSI_DIM == 2 ? 0.5 * (1.0 - 1.0 / (r.lz * r.lz)) : 0.0;
            const double tr = fsi_mat_trace(e) + e_zz, j = fsi_mat_det(f) * r.lz;
            const double w = j * (0.5 * lam * tr * tr + mu * (fsi_mat_ddot(e, e) + e_zz * e_zz));
            double worst = 0.0;
            for (int a = 0; a < FSI_DIM; a++)
                for (int b = 0; b < FSI_DIM; b++)
                    worst = fmax(worst, fabs(r.sigma[fsi_voigt_index(a, b)] -
                                             (2.0 * mu * FSI_MAT(e, a, b) + (a == b) * lam * tr)));
            if (FSI_DIM == 2)
                worst = fmax(worst, fabs(r.sigma[2] - (2.0 * mu * e_zz + lam * tr)));
            /* I - F^-T F^-1 in the test loses a digit to cancellation (strains 0.1). */
            CHECK(worst <= ROUND_OFF * sym6_max(r.sigma) && fabs(r.w - w) <= ROUND_OFF * w,
                  "%s: sigma off Hooke(e) by %.3g of %.3g, W %.17g (definition %.17g)",
                  label(&m), worst, sym6_max(r.sigma), r.w, w);
        }
    }
}

/* (h) Refusals write nothing; the fallbacks and helpers. */
static void test_refusals(void)
{
    const double sentinel = 12345.0;
    double bad[4][FSI_MAT_SIZE];
    for (int b = 0; b < 4; b++)
        fsi_mat_identity(bad[b]);
    for (int k = 0; k < FSI_MAT_SIZE; k++)
        bad[0][k] = 1.0;                       /* det F = 0 */
    bad[1][0] = -1.0;                          /* a reflection, det F = -1 */
    bad[2][1] = NAN;
    bad[3][0] = INFINITY;
    for (int l = 0; l < N_LAWS + 1; l++)
        for (int pl = 0; pl < N_PLANES; pl++) {
            const material_kind kind = l < N_LAWS ? LAWS[l] : MATERIAL_DRUCKER_PRAGER;
            const material m = make(kind, PLANES[pl]);
            for (int b = 0; b < 4 + (kind == MATERIAL_DRUCKER_PRAGER); b++) {
                double f[FSI_MAT_SIZE];
                if (b < 4)
                    fsi_mat_copy(bad[b], f);
                else
                    fsi_mat_identity(f);       /* Drucker-Prager: even at F = I */
                double p[FSI_MAT_SIZE], s[6], w = sentinel, lz = sentinel;
                for (int k = 0; k < FSI_MAT_SIZE; k++)
                    p[k] = sentinel;
                for (int k = 0; k < 6; k++)
                    s[k] = sentinel;
                const int rc = material_total_stress(&m, f, p, s, &w, &lz);
                int untouched = w == sentinel && lz == sentinel;
                for (int k = 0; k < FSI_MAT_SIZE; k++)
                    untouched &= p[k] == sentinel;
                for (int k = 0; k < 6; k++)
                    untouched &= s[k] == sentinel;
                CHECK(rc == -1 && untouched, "%s: case %d: rc %d, outputs %s", label(&m), b, rc,
                      untouched ? "untouched" : "written");
            }
        }
#if FSI_DIM == 2
    /* Plane stress without a real F_zz: SVK stretched equibiaxially to 1.5 (in-plane
     * tr E = 1.25 > (1 - nu) / (2 nu) = 0.75), Almansi-Hooke compressed to 0.5 (tr e =
     * -3 < -0.75); neo-Hookean always has one (and the Newton start works from both). */
    double f[FSI_MAT_SIZE] = {1.5, 0, 0, 1.5}, g[FSI_MAT_SIZE] = {0.5, 0, 0, 0.5};
    const material svk = make(MATERIAL_SAINT_VENANT_KIRCHHOFF, MATERIAL_PLANE_STRESS);
    const material le = make(MATERIAL_LINEAR_ELASTIC, MATERIAL_PLANE_STRESS);
    const material nh = make(MATERIAL_NEO_HOOKEAN, MATERIAL_PLANE_STRESS);
    double p[FSI_MAT_SIZE];
    CHECK(material_total_stress(&svk, f, p, NULL, NULL, NULL) == -1,
          "SVK plane stress at 1.5 equibiaxial has no thickness stretch");
    CHECK(material_total_stress(&le, g, p, NULL, NULL, NULL) == -1,
          "Almansi-Hooke plane stress at 0.5 equibiaxial has no thickness stretch");
    CHECK(material_total_stress(&svk, g, p, NULL, NULL, NULL) == 0 &&
              material_total_stress(&le, f, p, NULL, NULL, NULL) == 0,
          "SVK compressed and Almansi-Hooke stretched do have one");
    for (int e = -3; e <= 3; e++) {
        const double s = pow(10.0, e);
        double h[FSI_MAT_SIZE] = {s, 0, 0, s}, lz = 0.0, sg[6];
        const int rc = material_total_stress(&nh, h, p, sg, NULL, &lz);
        CHECK(rc == 0 && lz > 0.0 && fabs(sg[2]) <= ROUND_OFF * sym6_max(sg),
              "neo_hookean plane stress at equibiaxial %g: rc %d, F_zz %g, sigma_zz %g", s, rc,
              lz, sg[2]);
    }
#endif
    /* The optional outputs may be NULL. */
    double f1[FSI_MAT_SIZE], p1[FSI_MAT_SIZE];
    random_f(0.2, f1);
    const material nh3 = make(MATERIAL_NEO_HOOKEAN, MATERIAL_PLANE_STRAIN);
    CHECK(material_total_stress(&nh3, f1, p1, NULL, NULL, NULL) == 0, "NULL outputs accepted");

    /* material_update poisons the stress of a hyperelastic kind, leaves Hooke alone. */
    for (int l = 0; l < N_LAWS; l++) {
        const material m = make(LAWS[l], MATERIAL_PLANE_STRAIN);
        double deps[6] = {1e-4, 0, 0, 0, 0, 0}, s[6] = {0};
        material_update(&m, deps, s, NULL);
        int nan = 1;
        for (int k = 0; k < 6; k++)
            nan &= isnan(s[k]);
        CHECK(nan == material_is_hyperelastic(&m) && (nan || isfinite(s[0])),
              "%s: material_update gives %s", label(&m), nan ? "NaN" : "a stress");
    }
    int truth = 0;
    for (material_kind k = MATERIAL_LINEAR_ELASTIC; k <= MATERIAL_NEO_HOOKEAN; k++) {
        const material m = make(k, MATERIAL_PLANE_STRAIN);
        truth |= material_is_hyperelastic(&m) << k;
    }
    CHECK(truth == (1 << MATERIAL_SAINT_VENANT_KIRCHHOFF | 1 << MATERIAL_NEO_HOOKEAN),
          "material_is_hyperelastic: exactly SVK and neo-Hookean (bits %#x)", (unsigned)truth);
    CHECK(strcmp(material_kind_name(MATERIAL_SAINT_VENANT_KIRCHHOFF), "saint_venant_kirchhoff") ==
                  0 &&
              strcmp(material_kind_name(MATERIAL_NEO_HOOKEAN), "neo_hookean") == 0 &&
              strcmp(material_kind_name(MATERIAL_LINEAR_ELASTIC), "linear_elastic") == 0 &&
              strcmp(material_kind_name(MATERIAL_DRUCKER_PRAGER), "drucker_prager") == 0,
          "material_kind_name");
}

int main(void)
{
    rng_state = 20;
    test_derivative();
    test_objectivity();
    test_reference_state();
    test_small_strain();
    test_cauchy_and_plane_stress();
    test_uniaxial_stretch();
    test_almansi_hooke_definition();
    test_refusals();
    return unit_check_report("test_hyperelastic");
}
