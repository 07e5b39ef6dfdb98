/* NOSB-PD kinematics: small-tensor algebra, the shape tensor K (000 Eq. 34), the
 * deformation gradient F (Eq. 36) and the Hughes-Winget objective update
 * (Eqs. 37-46).
 *
 * Tolerances: quantities that are exact in real arithmetic are checked to a few
 * hundred ulps relative to their scale (1e-13), which any wrong index, weight or
 * bond set exceeds by orders of magnitude; the rotation test accumulates 90
 * increments and allows 1e-13 E of round-off per increment. */
#include "test_nosbpd_common.h"

#include "nosbpd_stress_update.h"

static const char *CASE_BASE = "[solid]\n"
                               "solver = nosbpd\n"
                               "density = 1000\n"
                               "youngs_modulus = 1e6\n"
                               "poisson_ratio = 0.25\n"
                               "plane = strain\n";

static double max_abs_diff(const double *a, const double *b, int n)
{
    double m = 0.0;
    for (int k = 0; k < n; k++)
        m = fmax(m, fabs(a[k] - b[k]));
    return m;
}

/* A shape tensor of points on one line is rank one; its inverse must be refused. In
 * 3D its det and adjugate are both round-off, which the condition test alone can
 * mistake for a well-conditioned matrix (seen: "condition" 8.7). */
static void check_rank_one_refused(void)
{
    const double dir[3] = {0.37, -0.81, 0.29};
    double k[FSI_MAT_SIZE], inv[FSI_MAT_SIZE];
    fsi_mat_zero(k);
    for (int n = -2; n <= 2; n++) {
        if (n == 0)
            continue;
        double xi[FSI_DIM];
        for (int d = 0; d < FSI_DIM; d++)
            xi[d] = 0.01 * n * dir[d];
        fsi_mat_add_outer(k, 1.0 / fabs((double)n), xi, xi);
    }
    CHECK(fsi_mat_inverse(k, inv, 1e8) == -1, "a rank-one shape tensor was inverted");
}

static void check_small_tensor(void)
{
    double a[FSI_MAT_SIZE], inv[FSI_MAT_SIZE], prod[FSI_MAT_SIZE], id[FSI_MAT_SIZE];
    for (int k = 0; k < FSI_MAT_SIZE; k++)
        a[k] = test_uniform() - 0.5;
    for (int d = 0; d < FSI_DIM; d++)
        FSI_MAT(a, d, d) += 2.0;
    CHECK(fsi_mat_inverse(a, inv, 1e8) == 0, "well-conditioned matrix not inverted");
    fsi_mat_mul(a, inv, prod);
    fsi_mat_identity(id);
    CHECK(max_abs_diff(prod, id, FSI_MAT_SIZE) < 1e-14, "a a^-1 differs from I by %g",
          max_abs_diff(prod, id, FSI_MAT_SIZE));

    /* Singular (rank one) and ill-conditioned matrices are refused, out untouched. */
    double u[FSI_DIM], s[FSI_MAT_SIZE], keep[FSI_MAT_SIZE];
    for (int d = 0; d < FSI_DIM; d++)
        u[d] = d + 1.0;
    fsi_mat_zero(s);
    fsi_mat_add_outer(s, 2.0, u, u);
    for (int k = 0; k < FSI_MAT_SIZE; k++)
        keep[k] = inv[k];
    CHECK(fsi_mat_inverse(s, inv, 1e8) == -1, "rank-one matrix inverted");
    CHECK(max_abs_diff(inv, keep, FSI_MAT_SIZE) == 0.0, "failed inverse wrote its output");
    fsi_mat_identity(s);
    FSI_MAT(s, 0, 0) = 1e-9;
    CHECK(fsi_mat_inverse(s, inv, 1e6) == -1, "condition 1e9 accepted with limit 1e6");
    CHECK(fsi_mat_inverse(s, inv, 1e12) == 0, "condition 1e9 refused with limit 1e12");
    s[0] = NAN;
    CHECK(fsi_mat_inverse(s, inv, 1e12) == -1, "NaN matrix inverted");

    /* sym + skew = a; det of a product. */
    double sy[FSI_MAT_SIZE], sk[FSI_MAT_SIZE];
    fsi_mat_sym(a, sy);
    fsi_mat_skew(a, sk);
    fsi_mat_axpy(sy, 1.0, sk, prod);
    CHECK(max_abs_diff(prod, a, FSI_MAT_SIZE) < 1e-16, "sym + skew != a");
    fsi_mat_mul(a, a, prod);
    CHECK(fabs(fsi_mat_det(prod) - fsi_mat_det(a) * fsi_mat_det(a)) < 1e-13,
          "det(a a) != det(a)^2");

    /* A 6-component tensor rotated by 90 degrees about z: xx <-> yy, xy -> -xy. */
    double r[FSI_MAT_SIZE];
    fsi_mat_identity(r);
    FSI_MAT(r, 0, 0) = 0.0, FSI_MAT(r, 0, 1) = -1.0, FSI_MAT(r, 1, 0) = 1.0,
                 FSI_MAT(r, 1, 1) = 0.0;
    double t6[6] = {1.0, 2.0, 3.0, 0.5, 0.0, 0.0};
    fsi_sym6_rotate(r, t6);
    CHECK(t6[0] == 2.0 && t6[1] == 1.0 && t6[2] == 3.0 && t6[3] == -0.5,
          "rotated tensor (%g %g %g %g)", t6[0], t6[1], t6[2], t6[3]);
}

/* K of a point deep in the lattice equals the lattice sum computed here directly. */
static void check_shape_tensor(const char *influence)
{
    const int side = 15, centre = 7;
    const double dx = 0.01, m_factor = 3.0, delta = m_factor * dx;
    solid_particles *p = test_lattice(side, side, side, dx, 1000.0);
    char text[512];
    snprintf(text, sizeof text, "%s[solid.nosbpd]\n"
                                "influence_function = %s\nhorizon_factor = %g\n", CASE_BASE,
             influence, m_factor);
    solid_model *m = test_model(text, p);

    double k[FSI_MAT_SIZE];
    fsi_mat_zero(k);
    int count = 0;
    const int r = 4;
    int idx[3] = {0, 0, 0};
    for (idx[2] = (FSI_DIM == 3 ? -r : 0); idx[2] <= (FSI_DIM == 3 ? r : 0); idx[2]++)
        for (idx[1] = -r; idx[1] <= r; idx[1]++)
            for (idx[0] = -r; idx[0] <= r; idx[0]++) {
                double xi[FSI_DIM], len = 0.0;
                for (int d = 0; d < FSI_DIM; d++) {
                    xi[d] = idx[d] * dx;
                    len += xi[d] * xi[d];
                }
                len = sqrt(len);
                if (len == 0.0 || len > delta * (1 + 1e-9))
                    continue;
                double w = 1.0;
                if (strcmp(influence, "inverse") == 0)
                    w = delta / len;
                else if (strcmp(influence, "gaussian") == 0)
                    w = exp(-4.0 * len * len / (delta * delta));
                fsi_mat_add_outer(k, w * pow(dx, FSI_DIM), xi, xi);
                count++;
            }
    int i = centre + side * centre + (FSI_DIM == 3 ? side * side * centre : 0);
    CHECK(nosbpd_full_family_count(m) == count, "%s: full family %d bonds, lattice sum %d",
          influence, nosbpd_full_family_count(m), count);
    if (FSI_DIM == 2)
        CHECK(count == 28, "a 3 dx horizon holds %d lattice points, expected 28", count);
    const nosbpd_bonds *b = nosbpd_model_bonds(m);
    CHECK(b->offset[i + 1] - b->offset[i] == count, "%s: centre point has %ld bonds, not %d",
          influence, (long)(b->offset[i + 1] - b->offset[i]), count);

    double k_inv_ref[FSI_MAT_SIZE];
    CHECK(fsi_mat_inverse(k, k_inv_ref, 1e8) == 0, "analytic K singular");
    const double *k_inv = nosbpd_shape_tensor_inverse(m) + i * FSI_MAT_SIZE;
    const double err = max_abs_diff(k_inv, k_inv_ref, FSI_MAT_SIZE) / fsi_mat_norm(k_inv_ref);
    CHECK(err < 1e-13, "%s: K^-1 of the centre point off the lattice sum by %g (relative)",
          influence, err);
    /* Lattice symmetry: K is isotropic (a multiple of I). */
    for (int a = 0; a < FSI_DIM; a++)
        for (int c = 0; c < FSI_DIM; c++) {
            CHECK(FSI_MAT(k_inv, a, c) == FSI_MAT(k_inv, c, a), "%s: K^-1 not symmetric",
                  influence);
            if (a != c)
                CHECK(fabs(FSI_MAT(k, a, c)) < 1e-13 * FSI_MAT(k, a, a),
                      "%s: lattice K has off-diagonal %g", influence, FSI_MAT(k, a, c));
        }
    /* Every point's K^-1 is exactly symmetric. */
    int asym = 0;
    for (int j = 0; j < p->n; j++) {
        const double *kj = nosbpd_shape_tensor_inverse(m) + j * FSI_MAT_SIZE;
        for (int a = 0; a < FSI_DIM; a++)
            for (int c = 0; c < FSI_DIM; c++)
                asym += FSI_MAT(kj, a, c) != FSI_MAT(kj, c, a);
    }
    CHECK(asym == 0, "%s: %d asymmetric entries of K^-1", influence, asym);
    solid_model_free(m);
    test_lattice_free(p);
}

/* x = A X + c: F = A at every point, edges and corners included (K and F sum over
 * the same bonds), and no force in the reference-stress-free body for a rotation. */
static void check_affine(void)
{
    const int nx = 12, ny = 9, nz = 5;
    solid_particles *p = test_lattice(nx, ny, nz, 0.02, 1000.0);
    solid_model *m = test_model(CASE_BASE, p);
    double a[FSI_MAT_SIZE];
    for (int k = 0; k < FSI_MAT_SIZE; k++)
        a[k] = 0.05 * (test_uniform() - 0.5);
    for (int d = 0; d < FSI_DIM; d++)
        FSI_MAT(a, d, d) += 1.0;
    double *x_prev = malloc((size_t)p->n * FSI_DIM * sizeof *x_prev);
    double *force = malloc((size_t)p->n * FSI_DIM * sizeof *force);
    memcpy(x_prev, p->x0, (size_t)p->n * FSI_DIM * sizeof *x_prev);
    for (int i = 0; i < p->n; i++) {
        double ax[FSI_DIM];
        fsi_mat_vec(a, p->x0 + i * FSI_DIM, ax);
        for (int d = 0; d < FSI_DIM; d++)
            p->x[i * FSI_DIM + d] = ax[d] + 0.3 * (d + 1);
    }
    CHECK(test_force(m, p, x_prev, force) == 0, "affine step failed");
    double worst = 0.0;
    for (int i = 0; i < p->n; i++)
        worst = fmax(worst, max_abs_diff(nosbpd_deformation_gradient(m) + i * FSI_MAT_SIZE, a,
                                         FSI_MAT_SIZE));
    CHECK(worst < 1e-13, "affine motion: F differs from A by up to %g", worst);
    free(x_prev);
    free(force);
    solid_model_free(m);
    test_lattice_free(p);
}

/* x = X + u(X) with u quadratic, u_d = 1/2 X . H_d X: the exact gradient is
 * F = I + [H_d X]. The quadratic fit (gradient_order = 2) must reproduce it at every
 * point whose family carries a quadratic fit, surface and corner points included,
 * to round-off (1e-12 against gradients of 1e-3). The linear fit of 000 Eq. 36 is
 * exact only where the family is symmetric; at the surface it sees the gradient at
 * its family's centroid, off by about |H| times a third of the horizon, so there
 * its error must exceed 10 % of |H| delta / 3: the case for order 2. */
static void check_quadratic(int gradient_order)
{
    const int nx = 14, ny = 10, nz = 8;
    const double dx = 0.01;
    solid_particles *p = test_lattice(nx, ny, nz, dx, 1000.0);
    char text[256];
    snprintf(text, sizeof text, "%s[solid.nosbpd]\n"
                                "gradient_order = %d\n", CASE_BASE, gradient_order);
    solid_model *m = test_model(text, p);
    double h[FSI_DIM][FSI_DIM][FSI_DIM];
    for (int d = 0; d < FSI_DIM; d++)
        for (int a = 0; a < FSI_DIM; a++)
            for (int b = 0; b <= a; b++)
                h[d][a][b] = h[d][b][a] = 0.02 * (test_uniform() - 0.5);
    double *x_prev = malloc((size_t)p->n * FSI_DIM * sizeof *x_prev);
    double *force = malloc((size_t)p->n * FSI_DIM * sizeof *force);
    double *exact = malloc((size_t)p->n * FSI_MAT_SIZE * sizeof *exact);
    memcpy(x_prev, p->x0, (size_t)p->n * FSI_DIM * sizeof *x_prev);
    for (int i = 0; i < p->n; i++) {
        const double *x0 = p->x0 + i * FSI_DIM;
        for (int d = 0; d < FSI_DIM; d++) {
            double u = 0.0;
            for (int a = 0; a < FSI_DIM; a++) {
                double g = 0.0;
                for (int b = 0; b < FSI_DIM; b++) {
                    u += 0.5 * x0[a] * h[d][a][b] * x0[b];
                    g += h[d][a][b] * x0[b];
                }
                exact[i * FSI_MAT_SIZE + d * FSI_DIM + a] = (a == d) + g;
            }
            p->x[i * FSI_DIM + d] = x0[d] + u;
        }
    }
    CHECK(test_force(m, p, x_prev, force) == 0, "order %d: quadratic step failed",
          gradient_order);
    double worst_fit = 0.0, worst_surface = 0.0;
    int fitted = 0;
    for (int i = 0; i < p->n; i++) {
        const double err = max_abs_diff(nosbpd_deformation_gradient(m) + i * FSI_MAT_SIZE,
                                        exact + i * FSI_MAT_SIZE, FSI_MAT_SIZE);
        if (!(nosbpd_point_flags(m)[i] & NOSBPD_POINT_LINEAR_FIT)) {
            worst_fit = fmax(worst_fit, err);
            fitted++;
        }
        worst_surface = fmax(worst_surface, err);
    }
    const double delta = nosbpd_horizon(m), h_scale = 0.01;
    if (gradient_order == 2) {
        CHECK(fitted == p->n, "order 2: %d of %d points fell back to the linear fit",
              p->n - fitted, p->n);
        CHECK(worst_fit < 1e-12, "order 2: F off the exact gradient by up to %g", worst_fit);
    } else {
        CHECK(worst_surface > 0.1 * h_scale * delta / 3.0,
              "order 1: surface error %g is not the expected centroid offset (~%g)",
              worst_surface, h_scale * delta / 3.0);
    }
    free(x_prev);
    free(force);
    free(exact);
    solid_model_free(m);
    test_lattice_free(p);
}

/* Rigid rotation by 90 degrees in 1-degree increments through Hughes-Winget: a
 * stress-free body stays stress-free and force-free; a pre-stress sigma_xx = s
 * turns with the body (at 45 degrees sigma_xy = +s/2, the sign that tells R from
 * R^T; at 90 degrees sigma_yy = s). */
static void check_rotation(double prestress, int gradient_order)
{
    const int nx = 10, ny = 7, nz = 4;
    solid_particles *p = test_lattice(nx, ny, nz, 0.01, 1000.0);
    char text[256];
    snprintf(text, sizeof text, "%s[solid.nosbpd]\n"
                                "gradient_order = %d\n", CASE_BASE, gradient_order);
    solid_model *m = test_model(text, p);
    double *stress = nosbpd_stress(m);
    for (int i = 0; i < p->n; i++)
        stress[i * 6 + 0] = prestress;
    double *x_prev = malloc((size_t)p->n * FSI_DIM * sizeof *x_prev);
    double *force = malloc((size_t)p->n * FSI_DIM * sizeof *force);
    const double pi = 3.14159265358979323846;
    double worst45 = 0.0, worst90 = 0.0, worst_force = 0.0;
    for (int step = 1; step <= 90; step++) {
        memcpy(x_prev, p->x, (size_t)p->n * FSI_DIM * sizeof *x_prev);
        const double th = step * pi / 180.0, c = cos(th), s = sin(th);
        for (int i = 0; i < p->n; i++) {
            const double *x0 = p->x0 + i * FSI_DIM;
            p->x[i * FSI_DIM + 0] = c * x0[0] - s * x0[1];
            p->x[i * FSI_DIM + 1] = s * x0[0] + c * x0[1];
        }
        if (test_force(m, p, x_prev, force) != 0) {
            CHECK(0, "rotation step %d failed", step);
            break;
        }
        for (int i = 0; i < p->n; i++) {
            const double *t = stress + i * 6;
            if (step == 45) {
                const double h = 0.5 * prestress;
                worst45 = fmax(worst45, fmax(fabs(t[0] - h), fmax(fabs(t[1] - h), fabs(t[3] - h))));
            }
            if (step == 90)
                worst90 = fmax(worst90, fmax(fabs(t[0]), fmax(fabs(t[1] - prestress), fabs(t[3]))));
            if (prestress == 0.0)
                for (int d = 0; d < FSI_DIM; d++)
                    worst_force = fmax(worst_force, fabs(force[i * FSI_DIM + d]));
        }
    }
    /* Round-off: each increment's strain is F_(n+1) - F_n of nearly equal matrices, good
     * to about 1e-15 (observed: 1e-9 Pa after 90 steps with E = 1e6 Pa); allow 1e-13 E
     * per increment. A wrong rotation is off by the pre-stress, no rotation by E 1e-2. */
    const double tol = 1e-13 * 1e6 * 90;
    CHECK(worst45 <= tol, "pre-stress %g: at 45 degrees the stress is off by %g", prestress,
          worst45);
    CHECK(worst90 <= tol, "pre-stress %g: at 90 degrees the stress is off by %g", prestress,
          worst90);
    /* Force scale of a strain of 1e-12: E dx^(DIM-1) 1e-12 = 1e-10 N. The quadratic fit
     * solves with a moment matrix whose condition number is some ten times K's (its
     * quadratic columns are nearly dependent on a small family), so allow ten times
     * that. A rotation treated as strain gives E dx 0.017 = 170 N per one-degree step. */
    const double force_tol = gradient_order == 1 ? 1e-10 : 1e-9;
    if (prestress == 0.0)
        CHECK(worst_force < force_tol, "order %d: rigid rotation produced forces up to %g N",
              gradient_order, worst_force);
    free(x_prev);
    free(force);
    solid_model_free(m);
    test_lattice_free(p);
}

/* The update alone: a uniaxial strain increment in the mid-point configuration gives
 * Hooke's increment; a pure rotation increment gives none. */
static void check_update_alone(void)
{
    material mat;
    memset(&mat, 0, sizeof mat);
    mat.kind = MATERIAL_LINEAR_ELASTIC;
    mat.plane = MATERIAL_PLANE_STRAIN;
    mat.density = 1000;
    mat.youngs_modulus = 1e6;
    mat.poisson_ratio = 0.25;
    material_derive(&mat);
    double f0[FSI_MAT_SIZE], f1[FSI_MAT_SIZE];
    fsi_mat_identity(f0);
    fsi_mat_identity(f1);
    FSI_MAT(f1, 0, 0) = 1.0 + 1e-4;
    double stress[6] = {0, 0, 0, 0, 0, 0}, lz = 1.0, work = 0.0;
    material_state st;
    memset(&st, 0, sizeof st);
    CHECK(nosbpd_hughes_winget(&mat, f0, f1, stress, &st, &lz, &work) == 0, "update failed");
    /* deps_xx = 1e-4 / (1 + 0.5e-4) on the mid-point configuration. */
    const double e = 1e-4 / (1.0 + 0.5e-4);
    const double sxx = (mat.lame_lambda + 2 * mat.shear_modulus) * e;
    CHECK(fabs(stress[0] - sxx) < 1e-12 * sxx, "sigma_xx %.15g, expected %.15g", stress[0], sxx);
    CHECK(fabs(stress[1] - mat.lame_lambda * e) < 1e-12 * sxx, "sigma_yy %.15g", stress[1]);
    /* Stress work per reference volume J_(n+1/2) sigma_(n+1/2) : deps. */
    const double w_ref = (1.0 + 0.5e-4) * 0.5 * sxx * e;
    CHECK(fabs(work - w_ref) < 1e-12 * w_ref, "work %.15g, expected %.15g", work, w_ref);
    /* A singular mid-point configuration is refused without touching the state. */
    double fz[FSI_MAT_SIZE];
    fsi_mat_zero(fz);
    for (int k = 0; k < FSI_MAT_SIZE; k++)
        fz[k] = -f0[k];
    const double keep = stress[0];
    CHECK(nosbpd_hughes_winget(&mat, f0, fz, stress, &st, &lz, &work) == -1,
          "singular F_(n+1/2) accepted");
    CHECK(stress[0] == keep, "refused update changed the stress");
}

int main(void)
{
    check_small_tensor();
    check_rank_one_refused();
    check_shape_tensor("one");
    check_shape_tensor("inverse");
    check_shape_tensor("gaussian");
    check_affine();
    check_quadratic(1);
    check_quadratic(2);
    check_update_alone();
    for (int order = 1; order <= 2; order++) {
        check_rotation(0.0, order);
        check_rotation(1000.0, order);
    }
    return unit_check_report("nosbpd kinematics");
}
