/* Fluid leaking through walls (fluid_solver/fluid_leak.h), with a tank like F1's: a
 * floor [-0.04, 1] x [-0.04, 0], a left wall [-0.04, 0] x [0, 0.3], no right wall, open
 * top; tolerance 0.036 m (one kernel support at dx = 0.01). Particles are moved in
 * small increments, one check after each, as the fluid's steps do:
 *  - through the floor: found once past the floor's bottom by more than the tolerance,
 *    not before; named with the wall, axis and direction;
 *  - into the floor and back out, over the top of the left wall and down outside, off
 *    the open end of the floor and back under it: never;
 *  - from outside the tank back in through the left wall: found;
 *  - along a periodic axis the wall's extent does not matter: a particle through the
 *    floor beyond its drawn ends (in a periodic image) is found;
 *  - a moving wall is where its motion puts it: a particle that stands still while the
 *    wall moves past it is found, one the wall does not reach is not;
 *  - after the particles are permuted the sides follow them;
 *  - fluid_leak_hold_and_check puts a particle that came into a wall back on the face
 *    it came through, with its velocity into the wall set to the wall's (a moving
 *    wall's too), and leaves alone one outside the walls or one inside since the start. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fluid_leak.h"
#include "unit_check.h"

#define N 4
static const double TOL = 0.036;

static fluid_box boxes[2];
static fluid_geometry geometry = {0.01, 2, 0, boxes, NULL};
static double x[N * FSI_DIM], v[N * FSI_DIM];
static int32_t id[N];
static uint8_t flags[N];
static fluid_particles p = {.n = N, .spacing = 0.01, .id = id, .x = x, .v = v, .flags = flags};

/* How many particles fluid_leak_hold_and_check puts back at t; -1 when it also finds a
 * crossing. */
static long hold(fluid_leak *l, double t)
{
    long held = 0;
    fluid_leak_crossing c;
    return fluid_leak_hold_and_check(l, &p, t, &held, &c) ? -1 : held;
}

static void set_wall(fluid_box *b, const char *section, double x0, double y0, double x1,
                     double y1)
{
    memset(b, 0, sizeof *b);
    b->section = section;
    b->is_wall = 1;
    b->shape.min[0] = x0, b->shape.min[1] = y0, b->shape.max[0] = x1, b->shape.max[1] = y1;
    for (int d = 2; d < FSI_DIM; d++)
        b->shape.min[d] = -1.0, b->shape.max[d] = 1.0;
}

static void place(int i, double px, double py)
{
    x[i * FSI_DIM] = px;
    x[i * FSI_DIM + 1] = py;
    for (int d = 2; d < FSI_DIM; d++)
        x[i * FSI_DIM + d] = 0.0;
}

/* Moves particle i in steps of at most 2 mm to (px, py), checking after each; returns
 * 1 at the first crossing found (with *c), 0 when none. */
static int move(fluid_leak *l, int i, double px, double py, double t, fluid_leak_crossing *c)
{
    const double x0 = x[i * FSI_DIM], y0 = x[i * FSI_DIM + 1];
    const int n = (int)ceil(hypot(px - x0, py - y0) / 0.002) + 1;
    for (int k = 1; k <= n; k++) {
        place(i, x0 + (px - x0) * k / n, y0 + (py - y0) * k / n);
        if (fluid_leak_check(l, &p, t, c))
            return 1;
    }
    return 0;
}

static void start(fluid_leak *l, const fsi_periodic *per)
{
    for (int i = 0; i < N; i++) {
        id[i] = 100 + i;
        flags[i] = FLUID_PARTICLE_FLUID;
        place(i, 0.1 + 0.2 * i, 0.05);
    }
    CHECK(fluid_leak_init(l, &geometry, per, TOL, &p, N, 0.0) == 0, "init");
}

int main(void)
{
    set_wall(&boxes[0], "fluid.wall floor", -0.04, -0.04, 1.0, 0.0);
    set_wall(&boxes[1], "fluid.wall left", -0.04, 0.0, 0.0, 0.3);
    fluid_leak l;
    fluid_leak_crossing c;

    start(&l, NULL);
    CHECK(!move(&l, 0, 0.1, -0.02, 0.0, &c) && !move(&l, 0, 0.1, 0.05, 0.0, &c),
          "into the floor and back out: no leak");
    CHECK(!move(&l, 1, 0.3, -0.04 - 0.9 * TOL, 0.0, &c), "within the tolerance: no leak");
    CHECK(move(&l, 1, 0.3, -0.2, 0.0, &c) && c.particle == 1 && c.box == 0 && c.axis == 1 &&
              !c.upward && fabs(c.face + 0.04) < 1e-12 &&
              x[1 * FSI_DIM + 1] < -0.04 - TOL && x[1 * FSI_DIM + 1] > -0.04 - TOL - 0.003,
          "through the floor: particle %d, wall %d, axis %d, upward %d, face %g, y %g",
          c.particle, c.box, c.axis, c.upward, c.face, x[1 * FSI_DIM + 1]);
    fluid_leak_free(&l);

    start(&l, NULL);
    CHECK(!move(&l, 0, 0.1, 0.35, 0.0, &c) && !move(&l, 0, -0.2, 0.35, 0.0, &c) &&
              !move(&l, 0, -0.2, -0.3, 0.0, &c),
          "over the top of the left wall and down outside: no leak");
    CHECK(!move(&l, 2, 1.1, 0.05, 0.0, &c) && !move(&l, 2, 1.1, -0.2, 0.0, &c) &&
              !move(&l, 2, 0.5, -0.2, 0.0, &c) && !move(&l, 2, 0.5, -0.05, 0.0, &c),
          "off the open end of the floor and back under it: no leak");
    fluid_leak_free(&l);

    start(&l, NULL);
    CHECK(!move(&l, 0, 0.1, 0.35, 0.0, &c) && !move(&l, 0, -0.2, 0.35, 0.0, &c) &&
              !move(&l, 0, -0.2, 0.1, 0.0, &c),
          "out over the left wall");
    CHECK(move(&l, 0, 0.2, 0.1, 0.0, &c) && c.particle == 0 && c.box == 1 && c.axis == 0 &&
              c.upward,
          "back in through the left wall: particle %d, wall %d, axis %d, upward %d",
          c.particle, c.box, c.axis, c.upward);
    fluid_leak_free(&l);

    fsi_periodic per = {{0}, {0}, {0}};
    per.on[0] = 1, per.lo[0] = -0.04, per.length[0] = 1.04;
    start(&l, &per);
    place(0, 1.5, 0.05);        /* beyond the floor's drawn end, in an image of it */
    CHECK(fluid_leak_check(&l, &p, 0.0, &c) == 0, "periodic start");
    CHECK(move(&l, 0, 1.5, -0.2, 0.0, &c) && c.box == 0 && c.axis == 1,
          "periodic along x: through the floor at x = 1.5");
    fluid_leak_free(&l);

    /* The left wall moves along x by X(t) = 0.2 sin(2 pi t): to [0.16, 0.2] at t = 0.25. */
    boxes[1].motion = (fluid_motion){FLUID_MOTION_HARMONIC, 0.2, 1.0, 0.0, {0}};
    boxes[1].motion.direction[0] = 1.0;
    start(&l, NULL);
    place(0, 0.05, 0.05);
    place(1, 0.3, 0.05);
    place(2, 0.5, 0.05);
    place(3, 0.7, 0.05);
    int found = 0;
    for (int k = 0; k <= 250 && !found; k++)
        found = fluid_leak_check(&l, &p, k * 0.001, &c);
    CHECK(found && c.particle == 0 && c.box == 1 && !c.upward,
          "a wall moving past a particle: found %d, particle %d", found, c.particle);
    fluid_leak_free(&l);
    start(&l, NULL);
    place(0, 0.3, 0.05);        /* the wall reaches x = 0.2 at most */
    found = 0;
    for (int k = 0; k <= 1000 && !found; k++)
        found = fluid_leak_check(&l, &p, k * 0.001, &c);
    CHECK(!found, "a particle beyond the wall's reach: no leak");
    fluid_leak_free(&l);
    boxes[1].motion.kind = FLUID_MOTION_NONE;

    start(&l, NULL);
    const int sorted[N] = {3, 2, 1, 0};     /* the particle now at k was at sorted[k] */
    double copy[N * FSI_DIM];
    int32_t ids[N];
    for (int k = 0; k < N; k++) {
        memcpy(&copy[k * FSI_DIM], &x[sorted[k] * FSI_DIM], FSI_DIM * sizeof *x);
        ids[k] = id[sorted[k]];
    }
    memcpy(x, copy, sizeof x);
    memcpy(id, ids, sizeof id);
    CHECK(fluid_leak_reorder(&l, sorted) == 0, "reorder");
    CHECK(move(&l, 3, x[3 * FSI_DIM], -0.2, 0.0, &c) && c.particle == 3 && id[3] == 100,
          "after a permutation: particle %d (id %d)", c.particle, id[c.particle]);
    fluid_leak_free(&l);

    /* Held at the walls. Particle 0 falls into the floor at (1, -2) m/s, particle 1 into
     * the left wall from the tank at (-2, 0.5) m/s, particle 2 leaves the floor upward,
     * particle 3 stays in the water. */
    start(&l, NULL);
    memset(v, 0, sizeof v);
    place(0, 0.3, 0.001);
    place(1, 0.002, 0.1);
    place(2, 0.6, 0.001);
    CHECK(fluid_leak_check(&l, &p, 0.0, &c) == 0, "hold: the sides before");
    place(0, 0.3, -0.005);
    v[0] = 1.0, v[1] = -2.0;
    place(1, -0.003, 0.1);
    v[FSI_DIM] = -2.0, v[FSI_DIM + 1] = 0.5;
    place(2, 0.6, -0.001);
    v[2 * FSI_DIM + 1] = 1.0;
    const long held = hold(&l, 0.0);
    CHECK(held == 3, "%ld particles held, expected 3", held);
    CHECK(x[1] == 0.0 && x[0] == 0.3 && v[0] == 1.0 && v[1] == 0.0,
          "into the floor: put at (%g, %g) with velocity (%g, %g), expected (0.3, 0) and "
          "(1, 0)", x[0], x[1], v[0], v[1]);
    CHECK(x[FSI_DIM] == 0.0 && x[FSI_DIM + 1] == 0.1 && v[FSI_DIM] == 0.0 &&
              v[FSI_DIM + 1] == 0.5,
          "into the left wall: put at (%g, %g) with velocity (%g, %g), expected (0, 0.1) and "
          "(0, 0.5)", x[FSI_DIM], x[FSI_DIM + 1], v[FSI_DIM], v[FSI_DIM + 1]);
    CHECK(x[2 * FSI_DIM + 1] == 0.0 && v[2 * FSI_DIM + 1] == 1.0,
          "leaving the floor: put at y = %g with v_y = %g, expected 0 and 1 (not into the wall)",
          x[2 * FSI_DIM + 1], v[2 * FSI_DIM + 1]);
    CHECK(x[3 * FSI_DIM] == 0.1 + 0.2 * 3 && x[3 * FSI_DIM + 1] == 0.05, "in the water: moved");
    CHECK(hold(&l, 0.0) == 0, "on the faces: no leak, nothing more to hold");
    fluid_leak_free(&l);

    /* Inside a wall since the start: its side is unknown, it is left where it is. */
    start(&l, NULL);
    place(0, 0.3, -0.02);
    fluid_leak_free(&l);
    CHECK(fluid_leak_init(&l, &geometry, NULL, TOL, &p, N, 0.0) == 0, "init");
    CHECK(hold(&l, 0.0) == 0 && x[1] == -0.02, "inside since the start: moved");
    fluid_leak_free(&l);

    /* A moving wall: the left wall at X(t) = 0.2 sin(2 pi t) moves at 0.4 pi m/s at
     * t = 0. A particle going into it at -1 m/s leaves with the wall's velocity. */
    boxes[1].motion = (fluid_motion){FLUID_MOTION_HARMONIC, 0.2, 1.0, 0.0, {0}};
    boxes[1].motion.direction[0] = 1.0;
    start(&l, NULL);
    memset(v, 0, sizeof v);
    place(0, 0.002, 0.1);
    CHECK(fluid_leak_check(&l, &p, 0.0, &c) == 0, "moving wall: the side before");
    place(0, -0.001, 0.1);
    v[0] = -1.0;
    CHECK(hold(&l, 0.0) == 1 && fabs(x[0]) < 1e-15 &&
              fabs(v[0] - 0.4 * M_PI) < 1e-12,
          "moving wall: put at x = %g with v_x = %g, expected 0 and %g", x[0], v[0], 0.4 * M_PI);
    fluid_leak_free(&l);
    boxes[1].motion.kind = FLUID_MOTION_NONE;
    return unit_check_report("test_fluid_leak");
}
