/* Prescribed wall motion (fluid_solver/fluid_motion.h, fluid_wall_motion.h):
 *  - a wall particle of a harmonic wall is at x0 + X(t), with velocity X'(t) and
 *    acceleration X''(t), at several times, X(0) = 0 whatever the phase;
 *  - X' and X'' are the derivatives of X (central differences);
 *  - fluid particles and fixed walls are left alone;
 *  - the health box is widened by the motion's reach (2 A along its direction);
 *  - with one law for every moving wall the walls' power is F . V with F the force
 *    sum m (a - g) on the fluid. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fluid_geometry.h"
#include "fluid_wall_motion.h"
#include "lattice_box.h"
#include "unit_check.h"

static const double PI = 3.14159265358979323846;

static void set_box(fluid_box *b, double x0, double x1, double spacing, int is_wall)
{
    memset(b, 0, sizeof *b);
    b->section = is_wall ? "fluid.wall w" : "fluid.block water";
    b->is_wall = is_wall;
    for (int d = 0; d < FSI_DIM; d++) {
        b->shape.min[d] = d == 0 ? x0 : 0.0;
        b->shape.max[d] = d == 0 ? x1 : 2.0 * spacing;
        b->shape.count[d] = (long)llround((b->shape.max[d] - b->shape.min[d]) / spacing);
    }
}

int main(void)
{
    const double dx = 0.1, A = 0.032, T = 1.3, phase = 60.0 * PI / 180.0;
    fluid_box boxes[3];
    set_box(&boxes[0], 0.0, 0.4, dx, 0);      /* water */
    set_box(&boxes[1], -0.2, 0.0, dx, 1);     /* moving wall */
    set_box(&boxes[2], 0.4, 0.6, dx, 1);      /* fixed wall */
    boxes[1].motion = (fluid_motion){FLUID_MOTION_HARMONIC, A, T, phase, {0}};
    boxes[1].motion.direction[0] = 0.6;
    boxes[1].motion.direction[FSI_DIM - 1] = 0.8;
    fluid_geometry g = {dx, 3, 0, boxes, NULL};
    fluid_particles p;
    unsigned char *free_slip = NULL;
    char msg[256];
    CHECK(fluid_geometry_build(&g, 1000.0, &p, &free_slip, msg, sizeof msg) == 0, "%s", msg);
    double *x_case = malloc((size_t)p.n * FSI_DIM * sizeof *x_case);
    memcpy(x_case, p.x, (size_t)p.n * FSI_DIM * sizeof *x_case);
    fluid_wall_motion w;
    CHECK(fluid_wall_motion_init(&w, &g, &p, msg, sizeof msg) == 0, "%s", msg);
    CHECK(w.n_moving == (int)fsi_lattice_points(boxes[1].shape.count) && w.tank == &boxes[1].motion,
          "moving particles: %d", w.n_moving);

    const double omega = 2.0 * PI / T, times[] = {0.0, 0.37, 1.0, 2.9};
    double worst = 0.0, worst_fixed = 0.0;
    for (size_t k = 0; k < sizeof times / sizeof times[0]; k++) {
        const double t = times[k];
        fluid_wall_motion_apply(&w, t, &p);
        const double s = A * (sin(omega * t + phase) - sin(phase)),
                     v = A * omega * cos(omega * t + phase),
                     a = -A * omega * omega * sin(omega * t + phase);
        for (int i = 0; i < p.n; i++) {
            const int moving = p.flags[i] == FLUID_PARTICLE_WALL && x_case[i * FSI_DIM] < 0.0;
            for (int d = 0; d < FSI_DIM; d++) {
                const int j = i * FSI_DIM + d;
                const double e = boxes[1].motion.direction[d];
                if (moving)
                    worst = fmax(worst, fabs(p.x[j] - (x_case[j] + s * e)) +
                                            fabs(p.v[j] - v * e) +
                                            fabs(p.boundary_acceleration[j] - a * e));
                else
                    worst_fixed = fmax(worst_fixed, fabs(p.x[j] - x_case[j]) + fabs(p.v[j]) +
                                                        fabs(p.boundary_acceleration[j]));
            }
        }
    }
    CHECK(worst < 1e-14, "moving wall particle off X(t), X'(t) or X''(t) by %g", worst);
    CHECK(worst_fixed == 0.0, "a fluid or fixed wall particle was moved (%g)", worst_fixed);

    /* Derivatives by central differences at t = 0.8 s. */
    const double t = 0.8, h = 1e-5;
    double xm[FSI_DIM], xp[FSI_DIM], vm[FSI_DIM], vp[FSI_DIM], v0[FSI_DIM], a0[FSI_DIM];
    fluid_motion_at(&boxes[1].motion, t - h, xm, vm, NULL);
    fluid_motion_at(&boxes[1].motion, t + h, xp, vp, NULL);
    fluid_motion_at(&boxes[1].motion, t, NULL, v0, a0);
    double worst_d = 0.0;
    for (int d = 0; d < FSI_DIM; d++)
        worst_d = fmax(worst_d, fabs((xp[d] - xm[d]) / (2 * h) - v0[d]) +
                                    fabs((vp[d] - vm[d]) / (2 * h) - a0[d]) / omega);
    CHECK(worst_d < 1e-8, "X' or X'' not the derivative of X: %g", worst_d);

    double lo[FSI_DIM] = {0}, hi[FSI_DIM] = {0};
    fluid_wall_motion_widen(&w, lo, hi);
    CHECK(fabs(hi[0] - 2 * A * 0.6) < 1e-15 && fabs(lo[FSI_DIM - 1] + 2 * A * 0.8) < 1e-15,
          "health box widened by %g, %g", hi[0], -lo[FSI_DIM - 1]);

    /* Every fluid particle pushed at 1 m/s^2 along x without gravity: F = M e_x. */
    double *acc = calloc((size_t)p.n * FSI_DIM, sizeof *acc), gravity[FSI_DIM] = {0}, mass = 0;
    for (int i = 0; i < p.n; i++)
        if (p.flags[i] & FLUID_PARTICLE_FLUID) {
            acc[i * FSI_DIM] = 1.0;
            mass += p.mass[i];
        }
    const double power = fluid_wall_motion_power(&w, 0.37, &p, acc, gravity);
    const double v_x = A * omega * cos(omega * 0.37 + phase) * 0.6;
    CHECK(fabs(power - mass * v_x) < 1e-12 * mass, "wall power %g, expected %g", power,
          mass * v_x);
    printf("wall motion: position/velocity/acceleration error %.3g, derivative error %.3g\n",
           worst, worst_d);

    free(acc);
    free(x_case);
    free(free_slip);
    fluid_wall_motion_free(&w);
    fluid_particles_free(&p);
    return unit_check_report("test_fluid_wall_motion");
}
