/* Particle shifting (isph_shifting.h). */
#include "isph_shifting.h"

#include <math.h>
#include <string.h>

#include "fluid_parallel.h"
#include "small_tensor.h"

/* The normal part of a shift next to the solid, damped (003 Eq. 27, our reading). */
static double damped_normal(double dn, double depth)
{
    if (!(depth > 0.0))
        return 0.0;
    const double x = fabs(dn) / depth;
    return copysign(depth * (x - 1.0 + exp(-x)), dn);
}

void isph_shifting_compute(const isph_shifting *c, const isph_pairs *q, const fluid_particles *p,
                           const isph_fields *f, double zeta, double *shift)
{
    const int n = p->n;
#pragma omp parallel for schedule(static) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        double *dr = &shift[i * FSI_DIM];
        memset(dr, 0, FSI_DIM * sizeof *dr);
        const int64_t lo = q->start[i], hi = q->start[i + 1];
        if (!(p->flags[i] & FLUID_PARTICLE_FLUID) || f->where[i] == ISPH_SPLASH || hi == lo ||
            !(c->coefficient > 0.0))
            continue;
        double mean = 0.0;
        for (int64_t e = lo; e < hi; e++)
            mean += sqrt(fsi_vec_dot(&q->xij[e * FSI_DIM], &q->xij[e * FSI_DIM]));
        mean /= (double)(hi - lo);
        double r_a[FSI_DIM] = {0};
        for (int64_t e = lo; e < hi; e++) {
            const double *x = &q->xij[e * FSI_DIM];
            const double r2 = fsi_vec_dot(x, x), r = sqrt(r2);
            if (!(r > 0.0))
                continue;
            for (int d = 0; d < FSI_DIM; d++)
                r_a[d] -= mean * mean / r2 * x[d] / r;   /* e_ab = -x / r */
        }
        for (int d = 0; d < FSI_DIM; d++)
            dr[d] = c->coefficient * zeta * r_a[d];
        const double len = fsi_vec_norm(dr);
        if (len > c->cap)
            for (int d = 0; d < FSI_DIM; d++)
                dr[d] *= c->cap / len;
        if (f->where[i] == ISPH_SURFACE || f->where[i] == ISPH_NEAR_SURFACE) {
            const double *nrm = &f->normal[i * FSI_DIM];
            const double dn = fsi_vec_dot(dr, nrm);
            for (int d = 0; d < FSI_DIM; d++)
                dr[d] -= dn * nrm[d];
        }
        const double *ns = &f->solid_normal[i * FSI_DIM];
        if (fsi_vec_dot(ns, ns) > 0.0) {
            const double rn = fabs(fsi_vec_dot(r_a, ns)), dn = fsi_vec_dot(dr, ns);
            const double depth = rn > 0.0 ? c->layer * zeta / rn : 0.0;
            const double change = damped_normal(dn, depth) - dn;
            for (int d = 0; d < FSI_DIM; d++)
                dr[d] += change * ns[d];
        }
    }
}
