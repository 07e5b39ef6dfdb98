/* The fluid's moving boundary particles (fluid_solver/fluid_boundary.h), the set fed
 * from the coupling each window:
 *  - a set of solid particles lands in the tail after the fixed particles, which stay
 *    untouched, with the solid's ids, positions, velocities, volumes and densities
 *    (boundary_density, bit for bit as sent; 0 on the fixed particles), kind
 *    MOVING_BOUNDARY and mass rho0 V0;
 *  - the set may grow, shrink and empty from one window to the next;
 *  - inside a window the tail moves at constant acceleration: x_k + v_k tau + a_k tau^2/2
 *    (exact up to round-off: tolerance 1e-14 m on positions of order 1 m);
 *  - a message with a non-finite position, or a volume or density that is not positive,
 *    is refused with the particle named, and one without densities is refused; nothing
 *    changes. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "fluid_boundary.h"
#include "unit_check.h"

#define N_FIXED 7

static void make_fixed(fluid_particles *p)
{
    fluid_particles_alloc(p, N_FIXED, 0.01);
    for (int i = 0; i < N_FIXED; i++) {
        p->id[i] = i;
        p->flags[i] = i < 4 ? FLUID_PARTICLE_FLUID : FLUID_PARTICLE_WALL;
        p->density[i] = 1000.0 + i;
        p->mass[i] = 0.1 * (i + 1);
        for (int d = 0; d < FSI_DIM; d++)
            p->x[i * FSI_DIM + d] = 0.1 * i + d;
    }
}

static int fixed_unchanged(const fluid_particles *p)
{
    for (int i = 0; i < N_FIXED; i++) {
        if (p->id[i] != i || p->density[i] != 1000.0 + i || p->mass[i] != 0.1 * (i + 1) ||
            p->flags[i] != (i < 4 ? FLUID_PARTICLE_FLUID : FLUID_PARTICLE_WALL))
            return 0;
        for (int d = 0; d < FSI_DIM; d++)
            if (p->x[i * FSI_DIM + d] != 0.1 * i + d)
                return 0;
        if (p->boundary_density[i] != 0.0)
            return 0;
    }
    return 1;
}

/* An interface message of m particles; arrays sized for 16. */
typedef struct {
    int32_t id[16];
    double x[16 * FSI_DIM], v[16 * FSI_DIM], a[16 * FSI_DIM], volume[16], density[16];
    fsi_interface msg;
} solid_message;

static void make_message(solid_message *s, int m, int first_id)
{
    for (int k = 0; k < m; k++) {
        s->id[k] = first_id + k;
        s->volume[k] = 1e-4 * (k + 1);
        /* Not round numbers: a density converted or recomputed on the way would show. */
        s->density[k] = 2700.0 / 3.0 + 0.1 * first_id + 1e-3 * k;
        for (int d = 0; d < FSI_DIM; d++) {
            s->x[k * FSI_DIM + d] = 1.0 + 0.01 * k + 0.5 * d;
            s->v[k * FSI_DIM + d] = 0.3 * (d + 1) - 0.1 * k;
            s->a[k * FSI_DIM + d] = -9.81 * (d == 1) + 2.0 * k;
        }
    }
    s->msg = (fsi_interface){.n = m, .id = s->id, .position = s->x, .velocity = s->v,
                             .acceleration = s->a, .volume = s->volume,
                             .density = s->density};
}

int main(void)
{
    const double rho0 = 1000.0;
    fluid_particles p;
    make_fixed(&p);
    fluid_boundary b;
    fluid_boundary_init(&b, N_FIXED);
    solid_message s;
    char msg[256];

    const int sizes[] = {5, 12, 3, 0, 9};
    for (int w = 0; w < 5; w++) {
        const int m = sizes[w];
        make_message(&s, m, 100 * w);
        CHECK(fluid_boundary_set(&b, &p, &s.msg, rho0, msg, sizeof msg) == 0,
              "window %d: set of %d refused: %s", w, m, msg);
        CHECK(p.n == N_FIXED + m, "window %d: %d particles, expected %d", w, p.n, N_FIXED + m);
        CHECK(fixed_unchanged(&p), "window %d: the fixed particles changed", w);
        int tail_ok = 1;
        for (int k = 0; k < m; k++) {
            const int i = N_FIXED + k;
            tail_ok &= p.id[i] == 100 * w + k && p.flags[i] == FLUID_PARTICLE_MOVING_BOUNDARY &&
                       p.volume[i] == s.volume[k] && p.mass[i] == rho0 * s.volume[k] &&
                       p.density[i] == rho0 &&
                       memcmp(&p.boundary_density[i], &s.density[k], sizeof s.density[k]) == 0;
            for (int d = 0; d < FSI_DIM; d++)
                tail_ok &= p.x[i * FSI_DIM + d] == s.x[k * FSI_DIM + d] &&
                           p.v[i * FSI_DIM + d] == s.v[k * FSI_DIM + d];
        }
        CHECK(tail_ok, "window %d: the tail is not the solid's particles", w);

        /* Sub-steps inside the window. */
        const double tau = 3.7e-3;
        fluid_boundary_move(&b, &p, tau);
        double worst = 0.0;
        for (int k = 0; k < m * FSI_DIM; k++) {
            const double x = s.x[k] + s.v[k] * tau + 0.5 * s.a[k] * tau * tau;
            const double v = s.v[k] + s.a[k] * tau;
            worst = fmax(worst, fabs(p.x[N_FIXED * FSI_DIM + k] - x) +
                                    fabs(p.v[N_FIXED * FSI_DIM + k] - v));
        }
        CHECK(worst < 1e-14, "window %d: constant-acceleration motion off by %g", w, worst);
        CHECK(fixed_unchanged(&p), "window %d: moving the tail moved a fixed particle", w);
        int acc_ok = 1;
        for (int k = 0; k < (N_FIXED + m) * FSI_DIM; k++)
            acc_ok &= p.boundary_acceleration[k] ==
                      (k < N_FIXED * FSI_DIM ? 0.0 : s.a[k - N_FIXED * FSI_DIM]);
        CHECK(acc_ok, "window %d: accelerations not in the tail's slots", w);
    }

    /* Refused messages leave everything as it was. */
    const int n_before = p.n;
    make_message(&s, 4, 500);
    s.x[2 * FSI_DIM + 1] = NAN;
    CHECK(fluid_boundary_set(&b, &p, &s.msg, rho0, msg, sizeof msg) != 0 &&
              strstr(msg, "particle 502") && p.n == n_before && b.n == n_before - N_FIXED,
          "a NaN position was not refused with the particle named (msg: %s)", msg);
    make_message(&s, 4, 600);
    s.volume[3] = -1e-4;
    CHECK(fluid_boundary_set(&b, &p, &s.msg, rho0, msg, sizeof msg) != 0 &&
              strstr(msg, "particle 603") && p.n == n_before,
          "a negative volume was not refused with the particle named (msg: %s)", msg);
    make_message(&s, 4, 700);
    s.density[1] = 0.0;
    CHECK(fluid_boundary_set(&b, &p, &s.msg, rho0, msg, sizeof msg) != 0 &&
              strstr(msg, "particle 701") && p.n == n_before,
          "a zero density was not refused with the particle named (msg: %s)", msg);
    make_message(&s, 4, 800);
    s.density[2] = INFINITY;
    CHECK(fluid_boundary_set(&b, &p, &s.msg, rho0, msg, sizeof msg) != 0 &&
              strstr(msg, "particle 802") && p.n == n_before,
          "an infinite density was not refused with the particle named (msg: %s)", msg);
    make_message(&s, 4, 900);
    s.msg.density = NULL;
    CHECK(fluid_boundary_set(&b, &p, &s.msg, rho0, msg, sizeof msg) != 0 &&
              strstr(msg, "densities") && p.n == n_before,
          "a message without densities was not refused (msg: %s)", msg);
    CHECK(fixed_unchanged(&p), "a refused message changed the fixed particles");

    fluid_boundary_free(&b);
    fluid_particles_free(&p);
    return unit_check_report("test_fluid_boundary");
}
