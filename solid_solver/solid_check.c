/* The semantic check of a solid's geometry (solid_keys.h): what single-key
 * validation cannot see. It runs in `fsi run --check` before any process starts, so
 * it works from the case alone: it walks the lattice and counts, builds nothing.
 *
 * Decision on blocks that are not a whole number of spacings long: an ERROR, not a
 * warning. A lattice of round(L / dx) points would silently change the body's size
 * and mass by up to half a spacing (several percent of a thin plate's thickness),
 * which shifts exactly the frequencies and deflections the benchmarks compare; the
 * message proposes the nearest sizes and the spacing that fit instead. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "case_check.h"
#include "geometry.h"
#include "solid_interface.h"
#include "solid_keys.h"

static const char axis_name[3] = {'x', 'y', 'z'};

static int given(const fsi_case *c, const char *section, const char *key)
{
    const char *o = fsi_case_origin(c, section, key);
    return o && strcmp(o, "default") != 0;
}

static void check_blocks(fsi_case_checker *k, const solid_geometry *g)
{
    double dx = g->spacing;
    for (int b = 0; b < g->n_blocks; b++) {
        const solid_block *blk = &g->blocks[b];
        const double *min = blk->shape.min, *max = blk->shape.max;
        const int is_box = blk->shape.kind == FSI_SHAPE_BOX;
        if (fsi_shape_check(k, &blk->shape, blk->section, dx) > 0)
            continue;
        for (int d = 0; d < FSI_DIM && is_box; d++) {
            double n = solid_block_spacings(blk, dx, d);
            double size = max[d] - min[d];
            if (size <= 0) {
                fsi_case_problem(k, blk->section, "max",
                        "must exceed min along %c (min %.9g m, max %.9g m)", axis_name[d],
                        min[d], max[d]);
            } else if (n < 1.0 - SOLID_GEOMETRY_TOL) {
                fsi_case_problem(k, blk->section, "max",
                        "the block is %.6g m thick along %c, thinner than one spacing "
                        "(%.9g m): it would hold no particle", size, axis_name[d], dx);
            } else if (fabs(n - round(n)) > SOLID_GEOMETRY_TOL * fmax(1.0, n)) {
                double lo = floor(n), hi = ceil(n);
                fsi_case_problem(k, blk->section, "max",
                        "the block is %.6g spacings long along %c; the lattice needs a whole "
                        "number: use max = %.9g or %.9g along %c, or spacing = %.9g "
                        "(%.0f points) or %.9g (%.0f points)",
                        n, axis_name[d], min[d] + lo * dx, min[d] + hi * dx,
                        axis_name[d], size / lo, lo, size / hi, hi);
            }
        }
        for (int a = 0; a < b; a++) {
            const solid_block *other = &g->blocks[a];
            if (!solid_blocks_overlap(other, blk, dx))
                continue;
            if (!fsi_shape_is_plain_box(&other->shape) || !fsi_shape_is_plain_box(&blk->shape)) {
                fsi_case_problem(k, blk->section, NULL, "overlaps [%s] (%s): points would be "
                                 "created twice; let blocks touch, not overlap",
                                 other->section, fsi_case_where(k->c, other->section, NULL));
                continue;
            }
            const double *omin = other->shape.min, *omax = other->shape.max;
            char box[256];
            int len = 0;
            for (int d = 0; d < FSI_DIM && len < (int)sizeof box; d++)
                len += snprintf(box + len, sizeof box - (size_t)len, "%s%c %.6g..%.6g",
                                d ? ", " : "", axis_name[d], fmax(omin[d], min[d]),
                                fmin(omax[d], max[d]));
            fsi_case_problem(k, blk->section, NULL,
                    "overlaps [%s] (%s) in %s: points would be created twice; let blocks "
                    "touch, not overlap", other->section,
                    fsi_case_where(k->c, other->section, NULL), box);
        }
    }
}

static void check_regions(fsi_case_checker *k, const solid_geometry *g)
{
    static const char *const action_word[] = {"clamp", "load", "remove", "no_failure"};
    for (int r = 0; r < g->n_regions; r++) {
        const solid_region *reg = &g->regions[r];
        for (int d = 0; d < FSI_DIM; d++)
            if (reg->min[d] > reg->max[d])
                fsi_case_problem(k, reg->section, "max",
                                 "is below min along %c (min %.9g, max %.9g)", axis_name[d],
                                 reg->min[d], reg->max[d]);
        if (reg->action == SOLID_REGION_LOAD) {
            if (!given(k->c, reg->section, "force"))
                fsi_case_problem(k, reg->section, "force", "action = load needs the total force");
        } else {
            if (given(k->c, reg->section, "force"))
                fsi_case_problem(k, reg->section, "force",
                                 "only a region with action = load takes a "
                                 "force (this one has action = %s)",
                                 action_word[reg->action]);
            if (given(k->c, reg->section, "ramp_time"))
                fsi_case_problem(k, reg->section, "ramp_time",
                                 "only a region with action = load takes "
                                 "a ramp_time (this one has action = %s)",
                                 action_word[reg->action]);
        }
        const char *face = fsi_case_get(k->c, reg->section, "clamp_face");
        if (given(k->c, reg->section, "clamp_face") && face) {
            if (reg->action != SOLID_REGION_CLAMP)
                fsi_case_problem(k, reg->section, "clamp_face",
                                 "only a region with action = clamp takes "
                                 "a clamp_face (this one has action = %s)",
                                 action_word[reg->action]);
            else if (solid_clamp_face_parse(face) < -1)
                fsi_case_problem(k, reg->section, "clamp_face",
                                 "'%s' names an axis this %dD build does "
                                 "not have",
                                 face, FSI_DIM);
        }
    }
}

/* Walks every lattice point once: how many points each region selects (remove
 * regions: how many they remove; others: how many surviving points they hold),
 * how many survive, and the nearest surviving point of each probe. */
static void count_selections(fsi_case_checker *k, const solid_geometry *g)
{
    long *selected = calloc((size_t)g->n_regions + 1, sizeof *selected);
    double *nearest = malloc(((size_t)g->n_probes + 1) * sizeof *nearest);
    double(*nearest_x)[FSI_DIM] = malloc(((size_t)g->n_probes + 1) * sizeof *nearest_x);
    if (!selected || !nearest || !nearest_x) {
        fprintf(k->out, "%s: out of memory checking the solid's geometry\n",
                fsi_case_path(k->c));
        k->errors++;
        goto done;
    }
    for (int q = 0; q < g->n_probes; q++)
        nearest[q] = INFINITY;
    long survivors = 0;
    double x[FSI_DIM];
    fsi_shape_walk w;
    for (int b = 0; b < g->n_blocks; b++) {
        fsi_shape_walk_begin(&w, &g->blocks[b].shape, g->spacing);
        while (fsi_shape_walk_next(&w, x)) {
            int removed = 0;
            for (int r = 0; r < g->n_regions; r++)
                if (g->regions[r].action == SOLID_REGION_REMOVE &&
                    solid_region_contains(&g->regions[r], g->spacing, x)) {
                    selected[r]++;
                    removed = 1;
                }
            if (removed)
                continue;
            survivors++;
            for (int r = 0; r < g->n_regions; r++)
                if (g->regions[r].action != SOLID_REGION_REMOVE &&
                    solid_region_contains(&g->regions[r], g->spacing, x))
                    selected[r]++;
            for (int q = 0; q < g->n_probes; q++) {
                double d2 = 0.0;
                for (int d = 0; d < FSI_DIM; d++)
                    d2 += (x[d] - g->probes[q].point[d]) * (x[d] - g->probes[q].point[d]);
                if (d2 < nearest[q]) {
                    nearest[q] = d2;
                    memcpy(nearest_x[q], x, sizeof x);
                }
            }
        }
    }
    if (survivors == 0 && g->n_blocks > 0) {
        fsi_case_problem(k, g->blocks[0].section, NULL,
                         "the solid has no particles: every block is "
                         "empty or removed");
        goto done;
    }
    for (int r = 0; r < g->n_regions; r++)
        if (selected[r] == 0)
            fsi_case_problem(k, g->regions[r].section, NULL,
                    g->regions[r].action == SOLID_REGION_REMOVE
                        ? "removes no particle: no lattice point (at min + (i + 1/2) spacing "
                          "in each block) lies in its box"
                        : "selects no particle: no remaining lattice point (at min + "
                          "(i + 1/2) spacing in each block) lies in its box");
    for (int q = 0; q < g->n_probes; q++) {
        double dist = sqrt(nearest[q]);
        if (dist > g->spacing * (1.0 + SOLID_GEOMETRY_TOL)) {
            char at[128] = "";
            int len = 0;
            for (int d = 0; d < FSI_DIM; d++)
                len += snprintf(at + len, sizeof at - (size_t)len, "%s%.6g", d ? ", " : "",
                                nearest_x[q][d]);
            fsi_case_problem(k, g->probes[q].section, "point",
                    "is %.6g m from the nearest particle (at %s), more than one spacing: a "
                    "probe must lie on the solid", dist, at);
        }
    }
done:
    free(selected);
    free(nearest);
    free(nearest_x);
}

/* Distance from x to the segment a-b. */
static double distance_to_segment(const double *x, const double *a, const double *b)
{
    double ab2 = 0.0, t = 0.0, d2 = 0.0;
    for (int d = 0; d < FSI_DIM; d++) {
        ab2 += (b[d] - a[d]) * (b[d] - a[d]);
        t += (x[d] - a[d]) * (b[d] - a[d]);
    }
    t = ab2 > 0.0 ? fmin(fmax(t / ab2, 0.0), 1.0) : 0.0;
    for (int d = 0; d < FSI_DIM; d++) {
        const double e = x[d] - (a[d] + t * (b[d] - a[d]));
        d2 += e * e;
    }
    return sqrt(d2);
}

/* 1 when the crack separates at least one pair of neighbouring surviving lattice
 * points (at most a lattice diagonal apart): a crack outside the body, or lying on a
 * lattice row, breaks nothing and is surely a mistake. Only points within a diagonal
 * of the crack can be such a pair. */
static int crack_cuts_lattice(const solid_geometry *g, const solid_crack *crack, int *out_of_memory)
{
    const double dx = g->spacing, reach = sqrt((double)FSI_DIM) * dx * (1.0 + SOLID_GEOMETRY_TOL);
    double(*near)[FSI_DIM] = NULL, x[FSI_DIM];
    long n = 0, capacity = 0;
    int cuts = 0;
    fsi_shape_walk w;
    for (int b = 0; b < g->n_blocks; b++) {
        fsi_shape_walk_begin(&w, &g->blocks[b].shape, dx);
        while (fsi_shape_walk_next(&w, x)) {
            if (distance_to_segment(x, crack->from, crack->to) > reach ||
                solid_geometry_removed(g, x))
                continue;
            if (n == capacity) {
                capacity = capacity ? 2 * capacity : 64;
                double(*grown)[FSI_DIM] = realloc(near, (size_t)capacity * sizeof *near);
                if (!grown) {
                    *out_of_memory = 1;
                    free(near);
                    return 0;
                }
                near = grown;
            }
            memcpy(near[n++], x, sizeof x);
        }
    }
    for (long i = 0; i < n && !cuts; i++)
        for (long j = i + 1; j < n && !cuts; j++) {
            double d2 = 0.0;
            for (int d = 0; d < FSI_DIM; d++)
                d2 += (near[j][d] - near[i][d]) * (near[j][d] - near[i][d]);
            cuts = d2 <= reach * reach &&
                   solid_crack_cuts(near[i], near[j], crack->from, crack->to);
        }
    free(near);
    return cuts;
}

static void check_cracks(fsi_case_checker *k, const solid_geometry *g)
{
    for (int i = 0; i < g->n_cracks; i++) {
        const solid_crack *crack = &g->cracks[i];
        if (FSI_DIM != 2) {
            fsi_case_problem(k, crack->section, NULL,
                             "cracks are segments of 2D builds; this build is %dD", FSI_DIM);
            continue;
        }
        const double length = distance_to_segment(crack->from, crack->to, crack->to);
        if (length < SOLID_GEOMETRY_TOL * g->spacing) {
            fsi_case_problem(k, crack->section, "to", "equals 'from': the crack has no length");
            continue;
        }
        int out_of_memory = 0;
        if (!crack_cuts_lattice(g, crack, &out_of_memory))
            fsi_case_problem(k, crack->section, NULL,
                             out_of_memory ? "out of memory checking where the crack lies"
                                           : "separates no two neighbouring particles: it "
                                             "lies outside the solid or along a lattice "
                                             "row (draw it between rows)");
    }
}

static void check_mode(fsi_case_checker *k, const char *role)
{
    const char *iv = fsi_case_get(k->c, role, "initial_velocity");
    if (iv && strcmp(iv, "cantilever_mode") == 0 &&
        !(fsi_case_get_real(k->c, role, "mode_length", 0.0) > 0.0))
        fsi_case_problem(k, role, "mode_length",
                "initial_velocity = cantilever_mode needs the length from the clamp to the "
                "free end (> 0)");
}

/* A given interface_depth must cover the fluid's reach below the surface
 * (solid_interface_fluid_reach): shallower, the fluid's kernel would meet a skin with
 * nothing behind it (missing volume in its sums) wherever the solid is finer than it. */
static void check_interface_depth(fsi_case_checker *k, const char *role)
{
    const double depth = fsi_case_get_real(k->c, role, "interface_depth", 0.0);
    double dx_f = 0.0;
    const double reach = solid_interface_fluid_reach(k->c, &dx_f);
    if (given(k->c, role, "interface_depth") && depth > 0.0 && reach > 0.0 &&
        depth < reach * (1.0 - 1e-9))
        fsi_case_problem(k, role, "interface_depth",
                "%.6g m does not cover the fluid's reach below the surface, %.6g m (its "
                "support radius, [fluid] support = %.6g m, less half its spacing %.6g m): use "
                "at least that, or 0 to derive it", depth, reach, reach + 0.5 * dx_f, dx_f);
}

int solid_geometry_check(const fsi_case *c, const char *role, FILE *errors)
{
    fsi_case_checker k = {c, errors, 0};
    solid_geometry g;
    char msg[256];
    if (solid_geometry_read(&g, c, role, msg, sizeof msg) != 0) {
        fprintf(errors, "%s: %s\n", fsi_case_path(c), msg);
        return 1;
    }
    check_blocks(&k, &g);
    check_regions(&k, &g);
    if (k.errors == 0 && solid_geometry_lattice_size(&g) > SOLID_MAX_LATTICE)
        fsi_case_problem(&k, role, "spacing",
                         "the blocks would hold %.3g lattice points, more than "
                         "%.3g: use a larger spacing",
                         solid_geometry_lattice_size(&g), (double)SOLID_MAX_LATTICE);
    /* Counting on blocks of the wrong size or with inverted boxes would only repeat
     * those errors as "selects no particle". */
    if (k.errors == 0) {
        count_selections(&k, &g);
        check_cracks(&k, &g);
    }
    check_mode(&k, role);
    check_interface_depth(&k, role);
    solid_geometry_free(&g);
    return k.errors;
}
