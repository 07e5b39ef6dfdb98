/* The semantic check of a fluid case (fluid_keys.h). It runs in `fsi run --check`
 * before any process starts, from the case alone: it builds no particles.
 * As for the solid (solid_solver/solid_check.c), a box that is not a whole number of
 * spacings long is an error: rounding would silently change the depth of the water,
 * and with it the hydrostatic pressure every benchmark compares. */
#include <math.h>
#include <string.h>

#include "case_check.h"
#include "fluid_geometry.h"
#include "fluid_keys.h"
#include "fluid_periodic.h"
#include "fluid_step.h"

static const char axis_name[3] = {'x', 'y', 'z'};

static void check_box_sizes(fsi_case_checker *k, const fluid_geometry *g)
{
    const double dx = g->spacing;
    for (int b = 0; b < g->n_boxes; b++) {
        const fluid_box *box = &g->boxes[b];
        if (fsi_shape_check(k, &box->shape, box->section, dx) > 0 ||
            box->shape.kind != FSI_SHAPE_BOX)
            continue;
        const double *min = box->shape.min, *max = box->shape.max;
        for (int d = 0; d < FSI_DIM; d++) {
            double size = max[d] - min[d], n = fluid_box_spacings(box, dx, d);
            if (size <= 0) {
                fsi_case_problem(k, box->section, "max", "must exceed min along %c (min %.9g m, "
                        "max %.9g m)", axis_name[d], min[d], max[d]);
            } else if (n < 1.0 - FLUID_GEOMETRY_TOL) {
                fsi_case_problem(k, box->section, "max",
                                 "the box is %.6g m thick along %c, thinner "
                                 "than one spacing (%.9g m): it would hold no particle",
                                 size, axis_name[d], dx);
            } else if (fabs(n - round(n)) > FLUID_GEOMETRY_TOL * fmax(1.0, n)) {
                double lo = floor(n), hi = ceil(n);
                fsi_case_problem(
                    k, box->section, "max",
                    "the box is %.6g spacings long along %c; the "
                    "lattice needs a whole number: use max = %.9g or %.9g along %c, or "
                    "spacing = %.9g or %.9g",
                    n, axis_name[d], min[d] + lo * dx, min[d] + hi * dx, axis_name[d],
                    size / lo, size / hi);
            }
        }
    }
}

/* Water in a wall, a wall in a wall, water in water: particles would be created twice
 * or on top of each other. */
static void check_overlaps(fsi_case_checker *k, const fluid_geometry *g)
{
    for (int b = 0; b < g->n_boxes; b++)
        for (int a = 0; a < b; a++) {
            const fluid_box *p = &g->boxes[a], *q = &g->boxes[b];
            if (!fluid_boxes_overlap(p, q, g->spacing))
                continue;
            fsi_case_problem(k, q->section, NULL, "overlaps [%s] (%s): %s; let %s touch, not "
                    "overlap", p->section, fsi_case_where(k->c, p->section, NULL),
                    p->is_wall != q->is_wall ? "water inside a wall"
                                             : "particles would be created twice",
                    fsi_shape_is_plain_box(&p->shape) && fsi_shape_is_plain_box(&q->shape)
                        ? "boxes" : "shapes");
        }
}

static void check_probes(fsi_case_checker *k, const fluid_geometry *g)
{
    for (int q = 0; q < g->n_probes; q++) {
        int inside = 0;
        for (int b = 0; b < g->n_boxes && !inside; b++)
            inside = !g->boxes[b].is_wall &&
                     fluid_box_contains(&g->boxes[b], g->spacing, g->probes[q].point);
        if (!inside)
            fsi_case_problem(k, g->probes[q].section, "point",
                             "lies in no [fluid.block]: a pressure "
                             "probe must start in (or on the edge of) the water");
    }
}

/* A harmonic motion needs a direction; a probe can follow only a wall of the case. */
static void check_motion(fsi_case_checker *k, const fluid_geometry *g)
{
    for (int b = 0; b < g->n_boxes; b++) {
        const fluid_box *box = &g->boxes[b];
        double norm = 0.0;
        for (int d = 0; d < FSI_DIM; d++)
            norm += box->motion.direction[d] * box->motion.direction[d];
        if (box->motion.kind != FLUID_MOTION_NONE && !(norm > 0.0))
            fsi_case_problem(k, box->section, "motion_direction",
                             "is zero: a harmonic motion needs a direction");
    }
    for (int q = 0; q < g->n_probes; q++)
        if (g->probes[q].follow && g->probes[q].follow_box < 0)
            fsi_case_problem(k, g->probes[q].section, "follow",
                             "names no [fluid.wall %s] of this case", g->probes[q].follow);
}

static void check_sound_speed(fsi_case_checker *k, const char *role)
{
    if (fsi_case_get_real(k->c, role, "sound_speed", 0.0) > 0.0)
        return;
    if (!(fsi_case_get_real(k->c, role, "max_velocity", 0.0) > 0.0) &&
        !(fsi_case_get_real(k->c, role, "max_pressure", 0.0) > 0.0))
        fsi_case_problem(k, role, "sound_speed", "is 0 (derive it from 000 Eq. 7) but neither "
                "max_velocity nor max_pressure is given: give c0 or the expected largest "
                "velocity or pressure");
}

/* The step of the fluid at rest (fluid_step.h: every later step is shorter) against
 * FSI_MIN_STEP and FSI_MAX_STEPS up to end_time; the message names the input of the
 * binding limit farthest from an ordinary case (water, c0 below water's 1480 m/s,
 * millimetre spacing, the default CFL factors). */
static void check_step(fsi_case_checker *k, const char *role)
{
    fluid_step_limits l;
    fluid_step_limits_read(&l, k->c, role);
    if (!(l.sound_speed > 0.0))
        return;     /* check_sound_speed says why */
    const double dx = fsi_case_get_real(k->c, role, "spacing", 0.0);
    const char *own = fsi_case_solver_section(k->c, role);
    const double sf = fsi_case_get_real(k->c, own, "smoothing_factor", 1.2);
    const double acoustic = fluid_acoustic_step(&l, 0.0), viscous = fluid_viscous_step(&l);
    char what[256];
    if (acoustic <= viscous) {
        const char *c0_key = "sound_speed";
        if (!(fsi_case_get_real(k->c, role, "sound_speed", 0.0) > 0.0))
            c0_key = fsi_case_get_real(k->c, role, "max_velocity", 0.0) >=
                             sqrt(fsi_case_get_real(k->c, role, "max_pressure", 0.0) / l.density)
                         ? "max_velocity"
                         : "max_pressure";
        const fsi_step_factor f[] = {{role, c0_key, l.sound_speed, 1480.0, -1.0},
                                     {role, "spacing", dx, 1e-3, 1.0},
                                     {own, "smoothing_factor", sf, 1.2, 1.0},
                                     {l.cfl_acoustic_section, l.cfl_acoustic_key,
                                      l.cfl_acoustic, 0.25, 1.0}};
        snprintf(what, sizeof what, "the fluid's acoustic step limit cfl_acoustic h / c0 = "
                 "%g * %g m / %g m/s", l.cfl_acoustic, l.h, l.sound_speed);
        fsi_case_check_step(k, acoustic, what, f, (int)(sizeof f / sizeof f[0]));
    } else {
        const fsi_step_factor f[] = {{role, "viscosity", l.viscosity, 1e-3, -1.0},
                                     {role, "density", l.density, 1000.0, 1.0},
                                     {role, "spacing", dx, 1e-3, 2.0},
                                     {own, "smoothing_factor", sf, 1.2, 2.0},
                                     {role, "cfl_viscous", l.cfl_viscous, 0.125, 1.0}};
        snprintf(what, sizeof what, "the fluid's viscous step limit cfl_viscous rho0 h^2 / mu "
                 "= %g * %g kg/m^3 * (%g m)^2 / %g Pa s", l.cfl_viscous, l.density, l.h,
                 l.viscosity);
        fsi_case_check_step(k, viscous, what, f, (int)(sizeof f / sizeof f[0]));
    }
}

/* The period box: given, longer than three supports (the neighbour grid needs three
 * cells per period), a whole number of spacings (the lattice continues across the
 * boundary), and every box inside it along the periodic axes. */
static void check_periodic(fsi_case_checker *k, const fluid_geometry *g, const char *role)
{
    fsi_periodic per;
    char msg[256];
    const char *axes = fsi_case_get(k->c, role, "periodic");
    if (!axes || strcmp(axes, "none") == 0)
        return;
    if (fluid_periodic_read(k->c, role, &per, msg, sizeof msg) != 0) {
        fprintf(k->out, "%s\n", msg);
        k->errors++;
        return;
    }
    const double dx = g->spacing;
    const double support = fsi_case_get_real(k->c, role, FSI_CASE_SUPPORT_KEY, 0.0);
    for (int d = 0; d < FSI_DIM; d++) {
        if (!per.on[d])
            continue;
        const double n = per.length[d] / dx;
        if (per.length[d] < 3.0 * support)
            fsi_case_problem(k, role, "periodic_max", "the period along %c is %.6g m, shorter "
                             "than three kernel supports (%.6g m)", axis_name[d],
                             per.length[d], 3.0 * support);
        else if (fabs(n - round(n)) > FLUID_GEOMETRY_TOL * fmax(1.0, n))
            fsi_case_problem(k, role, "periodic_max", "the period along %c is %.6g spacings; "
                             "the lattice needs a whole number", axis_name[d], n);
        for (int b = 0; b < g->n_boxes; b++) {
            const fluid_box *box = &g->boxes[b];
            const double tol = FLUID_GEOMETRY_TOL * dx;
            if (box->shape.lo[d] < per.lo[d] - tol ||
                box->shape.hi[d] > per.lo[d] + per.length[d] + tol)
                fsi_case_problem(k, box->section, "min", "reaches outside the period box "
                                 "along %c (%.9g .. %.9g m): its particles would overlap "
                                 "their own images", axis_name[d], per.lo[d],
                                 per.lo[d] + per.length[d]);
        }
    }
}

int fluid_geometry_check(const fsi_case *c, const char *role, FILE *errors)
{
    fsi_case_checker k = {c, errors, 0};
    fluid_geometry g;
    char msg[256];
    if (fluid_geometry_read(&g, c, role, msg, sizeof msg) != 0) {
        fprintf(errors, "%s: %s\n", fsi_case_path(c), msg);
        return 1;
    }
    check_box_sizes(&k, &g);
    if (k.errors == 0)
        check_overlaps(&k, &g);
    if (k.errors == 0 && fluid_geometry_lattice_size(&g) > FLUID_MAX_LATTICE)
        fsi_case_problem(&k, role, "spacing",
                         "the boxes would hold %.3g particles, more than %.3g: "
                         "use a larger spacing",
                         fluid_geometry_lattice_size(&g), (double)FLUID_MAX_LATTICE);
    check_probes(&k, &g);
    check_motion(&k, &g);
    check_sound_speed(&k, role);
    check_step(&k, role);
    check_periodic(&k, &g, role);
    fluid_geometry_free(&g);
    return k.errors;
}
