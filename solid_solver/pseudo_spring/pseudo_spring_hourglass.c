/* Zero-energy (hourglass) control of the immediate-neighbour stencil: the energy of
 * the non-affine part of each point's neighbourhood motion.
 *
 * Why. The velocity gradient of Eq. 19 at an interior point, with the corrected
 * gradient over its 8 (26) immediate neighbours, is a central difference: the
 * weights of opposite neighbours are opposite and v_i itself drops out. Any field
 * that takes the same value at opposite neighbours, (-1)^i, (-1)^j, (-1)^(i+j) on
 * the lattice, has l = 0 at every interior point: zero-energy modes that the stress
 * never resists (the discrete operator D of Eq. 19 has a kernel; the power-consistent
 * force is D^T sigma, so nothing pushes back). Only the one-sided stencils at the
 * edges see them. S3 showed them growing (an x-alternating pattern of u_y, 30-40 mm
 * at the beam's faces by t = 0.04 s) and, at the amplitude of the case, taking over
 * the motion: period +40 % at dx = 0.1 m, the run unstable without the viscosity.
 *
 * What. Point i's neighbourhood in the reference lattice is fitted by an affine map:
 *     F_i = argmin_F sum_J w_iJ |x_iJ - F X_iJ|^2 = (sum_J w_iJ x_iJ (x) X_iJ) A0_i^-1,
 *     A0_i = sum_J w_iJ X_iJ (x) X_iJ,   w_iJ = V0_J (-F(|X_iJ|)) >= 0,
 * x_iJ = x_J - x_i, X_iJ = X_J - X_i over the intact links (the weights of the
 * corrected gradient of Eq. 20 in the reference configuration, so F_i is that
 * gradient of the positions), and the residual r_iJ = x_iJ - F_i X_iJ is the motion
 * no affine (strain plus rotation) field explains. The control stores
 *     E_i = G V0_i (sum_J w_iJ |r_iJ|^2) / (sum_J w_iJ |X_iJ|^2),
 * the energy V0 G |eps|^2 of a deviatoric strain of the size of the weighted RMS
 * residual strain |r| / |X|: the non-affine motion is priced at the softest stiffness
 * the isotropic material has for any strain (2 G, deviatoric), so it never costs more
 * than a real strain of that size would (times the key hourglass_control, default 1;
 * 0 is off). E_i is zero for every affine field (uniform strain, rigid motion: the
 * continuum answer is untouched), O(dx^2) relative to the strain energy for a smooth
 * field (the quadratic part of bending), and of the order of the strain energy for a
 * zero-energy mode. It depends on the positions only, is invariant under rigid
 * motions (so the forces conserve linear and angular momentum), and since F_i
 * minimises the fitted sum, dE_i/dF_i = 0 and the force is
 *     f_k = -dE/dx_k = sum_J [kappa_k w_kJ r_kJ - kappa_J w_Jk r_Jk],
 *     kappa_i = 2 G V0_i / sum_J w_iJ |X_iJ|^2,
 * over k's intact links (a link is intact at both ends): a gather with F_J computed
 * beforehand (pass 3), exactly the gradient of sum_i E_i, so the energy the main loop
 * checks (solid_model_strain_energy) includes it and closes. This is the idea of
 * Ganzenmueller's (2015) hourglass control for total-Lagrangian SPH (a penalty on
 * x_ij - F_i X_ij), here as the gradient of an energy rather than a pairwise spring
 * along the link, and scaled by the material's stiffness rather than a free constant.
 *
 * Mirrored clamp points are not material: no energy of their own (they only enter
 * their neighbours' fits as images). A point whose remaining links cannot fit an
 * affine map (A0 ill-conditioned or no link: after failure) stores nothing. */
#include <math.h>

#include "pseudo_spring_internal.h"

/* X_iJ = X_J - X_i of link q of point i, and its weight w_iJ (links.weight, set at
 * creation by ps_hourglass_weights). */
static double reference_link(const solid_model *m, const solid_particles *p, int i, int64_t q,
                             double *rx)
{
    const int j = m->links.neighbour[q];
    for (int d = 0; d < FSI_DIM; d++)
        rx[d] = p->x0[(int64_t)j * FSI_DIM + d] - p->x0[(int64_t)i * FSI_DIM + d];
    return m->links.weight[q];
}

void ps_hourglass_weights(solid_model *m, const solid_particles *p)
{
    solid_bonds *l = &m->links;
    for (int i = 0; i < m->n; i++)
        for (int64_t q = l->offset[i]; q < l->offset[i + 1]; q++) {
            const int j = l->neighbour[q];
            double r2 = 0.0, w, f;
            for (int d = 0; d < FSI_DIM; d++) {
                const double r = p->x0[(int64_t)j * FSI_DIM + d] - p->x0[(int64_t)i * FSI_DIM + d];
                r2 += r * r;
            }
            wendland_c2_eval2(&m->kernel, r2, &w, &f);
            l->weight[q] = -f * p->volume[j];
        }
}

/* H_i = F_i - I (the fitted displacement gradient) and kappa_i (0: no control at i)
 * into out. */
static void fit(const solid_model *m, const solid_particles *p, int i, double *out)
{
    for (int k = 0; k < PS_HOURGLASS_STRIDE; k++)
        out[k] = 0.0;
    if (!(m->hg_coefficient > 0.0) || (m->flags[i] & PS_POINT_GHOST))
        return;
    const solid_bonds *l = &m->links;
    const double *x = p->x;
    double a0[FSI_MAT_SIZE] = {0}, mx[FSI_MAT_SIZE] = {0}, z = 0.0;
    for (int64_t q = l->offset[i]; q < l->offset[i + 1]; q++) {
        if (!l->intact[q])
            continue;
        const int j = l->neighbour[q];
        double rx[FSI_DIM], rc[FSI_DIM];
        const double w = reference_link(m, p, i, q, rx);
        for (int d = 0; d < FSI_DIM; d++) {
            rc[d] = x[(int64_t)j * FSI_DIM + d] - p->x0[(int64_t)j * FSI_DIM + d] -
                    x[(int64_t)i * FSI_DIM + d] + p->x0[(int64_t)i * FSI_DIM + d];
            z += w * rx[d] * rx[d];
        }
        fsi_mat_add_outer(a0, w, rx, rx);
        fsi_mat_add_outer(mx, w, rc, rx);
    }
    double a0_inv[FSI_MAT_SIZE];
    if (!(z > 0.0) || fsi_mat_inverse(a0, a0_inv, PS_MAX_CONDITION_A) != 0)
        return;     /* the links cannot carry an affine fit: no control */
    fsi_mat_mul(mx, a0_inv, out);       /* H_i = F_i - I */
    out[FSI_MAT_SIZE] = 2.0 * m->hg_coefficient * m->mat.shear_modulus * p->volume[i] / z;
}

void ps_hourglass_factors(solid_model *m, const solid_particles *p, int i)
{
    fit(m, p, i, m->hourglass + (int64_t)i * PS_HOURGLASS_STRIDE);
}

/* r = x_iJ - F_i X_iJ = u_iJ - H_i X_iJ for the link (i, j), u = x - X, H_i = F_i - I
 * in fi (with the displacements, so that the reference configuration gives r = 0
 * exactly, not the round-off of x_iJ - X_iJ). */
static void residual(const solid_particles *p, const double *fi, int i, int j,
                     const double *rx, double *r)
{
    for (int a = 0; a < FSI_DIM; a++) {
        const int64_t kj = (int64_t)j * FSI_DIM + a, ki = (int64_t)i * FSI_DIM + a;
        double s = p->x[kj] - p->x0[kj] - p->x[ki] + p->x0[ki];
        for (int b = 0; b < FSI_DIM; b++)
            s -= fi[a * FSI_DIM + b] * rx[b];
        r[a] = s;
    }
}

void ps_hourglass_force(const solid_model *m, const solid_particles *p, int k, double *f)
{
    const solid_bonds *l = &m->links;
    const double *fk = m->hourglass + (int64_t)k * PS_HOURGLASS_STRIDE;
    for (int64_t q = l->offset[k]; q < l->offset[k + 1]; q++) {
        if (!l->intact[q])
            continue;
        const int j = l->neighbour[q];
        const double *fj = m->hourglass + (int64_t)j * PS_HOURGLASS_STRIDE;
        double rx[FSI_DIM], r[FSI_DIM];
        if (fk[FSI_MAT_SIZE] > 0.0) {
            const double w = reference_link(m, p, k, q, rx);
            residual(p, fk, k, j, rx, r);
            for (int d = 0; d < FSI_DIM; d++)
                f[d] += fk[FSI_MAT_SIZE] * w * r[d];
        }
        if (fj[FSI_MAT_SIZE] > 0.0) {
            const double w = reference_link(m, p, j, m->reverse[q], rx);
            residual(p, fj, j, k, rx, r);
            for (int d = 0; d < FSI_DIM; d++)
                f[d] -= fj[FSI_MAT_SIZE] * w * r[d];
        }
    }
}

double ps_hourglass_energy(const solid_model *m, const solid_particles *p, int i)
{
    double fi[PS_HOURGLASS_STRIDE];
    fit(m, p, i, fi);
    if (!(fi[FSI_MAT_SIZE] > 0.0))
        return 0.0;
    const solid_bonds *l = &m->links;
    double e = 0.0;
    for (int64_t q = l->offset[i]; q < l->offset[i + 1]; q++) {
        if (!l->intact[q])
            continue;
        double rx[FSI_DIM], r[FSI_DIM];
        const int j = l->neighbour[q];
        const double w = reference_link(m, p, i, q, rx);
        residual(p, fi, i, j, rx, r);
        for (int d = 0; d < FSI_DIM; d++)
            e += w * r[d] * r[d];
    }
    return 0.5 * fi[FSI_MAT_SIZE] * e;
}
