/* Water blocks, walls and probe points; the particles built from them
 * (fluid_geometry.h). */
#include "fluid_geometry.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "case_check.h"

static void read_vector(const fsi_case *c, const char *section, const char *key, double *out)
{
    if (fsi_case_get_vector(c, section, key, out) != 0)
        for (int d = 0; d < FSI_DIM; d++)
            out[d] = 0.0;
}


static void read_box(fluid_box *b, const fsi_case *c, const char *section, double spacing,
                     int is_wall)
{
    b->section = section;
    b->is_wall = is_wall;
    b->free_slip = is_wall && fsi_case_get_bool(c, section, "free_slip", 0);
    if (is_wall)
        fluid_motion_read(&b->motion, c, section);
    fsi_shape_read(&b->shape, c, section, spacing);
}

/* After the boxes: 'follow' names one of the walls. */
static void read_probe(fluid_probe_point *q, const fluid_geometry *g, const fsi_case *c,
                       const char *section)
{
    q->section = section;
    read_vector(c, section, "point", q->point);
    const char *quantity = fsi_case_get(c, section, "quantity");
    q->elevation = quantity && strcmp(quantity, "elevation") == 0;
    q->follow = fsi_case_get(c, section, "follow");
    if (q->follow && !q->follow[0])
        q->follow = NULL;       /* the default "": a fixed point */
    q->follow_box = -1;
    for (int b = 0; q->follow && b < g->n_boxes; b++) {
        const char *name = fsi_case_object_name(g->boxes[b].section);
        if (g->boxes[b].is_wall && name && strcmp(name, q->follow) == 0)
            q->follow_box = b;
    }
}

int fluid_geometry_read(fluid_geometry *g, const fsi_case *c, const char *role, char *msg,
                        size_t msg_size)
{
    memset(g, 0, sizeof *g);
    g->spacing = fsi_case_get_real(c, role, "spacing", 0.0);
    const char **blocks = NULL, **walls = NULL, **probes = NULL;
    int nb = fsi_case_object_list(c, role, "block", &blocks);
    int nw = fsi_case_object_list(c, role, "wall", &walls);
    int np = fsi_case_object_list(c, role, "probe", &probes);
    int ok = nb >= 0 && nw >= 0 && np >= 0;
    if (ok && nb + nw > 0) {
        g->boxes = calloc((size_t)(nb + nw), sizeof *g->boxes);
        ok = g->boxes != NULL;
    }
    if (ok && np > 0) {
        g->probes = calloc((size_t)np, sizeof *g->probes);
        ok = g->probes != NULL;
    }
    if (ok) {
        for (int i = 0; i < nb; i++)
            read_box(&g->boxes[i], c, blocks[i], g->spacing, 0);
        for (int i = 0; i < nw; i++)
            read_box(&g->boxes[nb + i], c, walls[i], g->spacing, 1);
        g->n_boxes = nb + nw;
        for (int i = 0; i < np; i++)
            read_probe(&g->probes[i], g, c, probes[i]);
        g->n_probes = np;
    }
    free(blocks);
    free(walls);
    free(probes);
    if (!ok) {
        fluid_geometry_free(g);
        snprintf(msg, msg_size, "out of memory reading the fluid's geometry");
        return -1;
    }
    return 0;
}

void fluid_geometry_free(fluid_geometry *g)
{
    free(g->boxes);
    free(g->probes);
    memset(g, 0, sizeof *g);
}

double fluid_box_spacings(const fluid_box *b, double spacing, int axis)
{
    return (b->shape.max[axis] - b->shape.min[axis]) / spacing;
}

double fluid_box_points(const fluid_box *b)
{
    return fsi_shape_points(&b->shape);
}

double fluid_geometry_lattice_size(const fluid_geometry *g)
{
    double n = 0.0;
    for (int b = 0; b < g->n_boxes; b++)
        n += fluid_box_points(&g->boxes[b]);
    return n;
}

int fluid_boxes_overlap(const fluid_box *a, const fluid_box *b, double spacing)
{
    return fsi_shapes_overlap(&a->shape, &b->shape, spacing);
}

int fluid_box_contains(const fluid_box *b, double spacing, const double *x)
{
    return fsi_shape_contains(&b->shape, FLUID_GEOMETRY_TOL * spacing, x);
}

int fluid_geometry_build(const fluid_geometry *g, double density, fluid_particles *p,
                         unsigned char **free_slip, char *msg, size_t msg_size)
{
    *free_slip = NULL;
    double total = fluid_geometry_lattice_size(g);
    if (total > FLUID_MAX_LATTICE || total < 1.0) {
        snprintf(msg, msg_size, "the fluid's boxes hold %.3g particles (1 to %.3g allowed)",
                 total, (double)FLUID_MAX_LATTICE);
        return -1;
    }
    int n = (int)total;
    if (fluid_particles_alloc(p, n, g->spacing) != 0 ||
        !(*free_slip = calloc((size_t)n, 1))) {
        fluid_particles_free(p);
        snprintf(msg, msg_size, "out of memory for %d fluid particles", n);
        return -1;
    }
    const double volume = pow(g->spacing, FSI_DIM);
    int i = 0;
    /* Boxes are stored blocks first, so fluid particles come before wall particles. */
    for (int b = 0; b < g->n_boxes; b++) {
        const fluid_box *box = &g->boxes[b];
        fsi_shape_walk w;
        fsi_shape_walk_begin(&w, &box->shape, g->spacing);
        for (; i < n && fsi_shape_walk_next(&w, p->x + i * FSI_DIM); i++) {
            p->id[i] = i;
            p->volume[i] = volume;
            p->mass[i] = density * volume;
            p->density[i] = density;
            p->flags[i] = box->is_wall ? FLUID_PARTICLE_WALL : FLUID_PARTICLE_FLUID;
            (*free_slip)[i] = (unsigned char)box->free_slip;
        }
    }
    return 0;
}
