/* Lattice from blocks, region selection, particles (geometry.h). */
#include "geometry.h"
#include "lattice_box.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "case_check.h"

static int read_vector(const fsi_case *c, const char *section, const char *key, double *out)
{
    if (fsi_case_get_vector(c, section, key, out) == 0)
        return 0;
    for (int d = 0; d < FSI_DIM; d++)
        out[d] = 0.0;
    return -1;
}

static solid_region_action action_of(const char *word)
{
    if (word && strcmp(word, "load") == 0)
        return SOLID_REGION_LOAD;
    if (word && strcmp(word, "remove") == 0)
        return SOLID_REGION_REMOVE;
    if (word && strcmp(word, "no_failure") == 0)
        return SOLID_REGION_NO_FAILURE;
    return SOLID_REGION_CLAMP;
}


int solid_geometry_read(solid_geometry *g, const fsi_case *c, const char *role, char *msg,
                        size_t msg_size)
{
    memset(g, 0, sizeof *g);
    g->spacing = fsi_case_get_real(c, role, "spacing", 0.0);
    const char **blocks = NULL, **regions = NULL, **probes = NULL, **cracks = NULL;
    int nb = fsi_case_object_list(c, role, "block", &blocks);
    int nr = fsi_case_object_list(c, role, "region", &regions);
    int np = fsi_case_object_list(c, role, "probe", &probes);
    int nc = fsi_case_object_list(c, role, "crack", &cracks);
    if (nb < 0 || nr < 0 || np < 0 || nc < 0)
        goto out_of_memory;
    g->blocks = nb ? calloc((size_t)nb, sizeof *g->blocks) : NULL;
    g->regions = nr ? calloc((size_t)nr, sizeof *g->regions) : NULL;
    g->probes = np ? calloc((size_t)np, sizeof *g->probes) : NULL;
    g->cracks = nc ? calloc((size_t)nc, sizeof *g->cracks) : NULL;
    if ((nb && !g->blocks) || (nr && !g->regions) || (np && !g->probes) ||
        (nc && !g->cracks))
        goto out_of_memory;

    g->n_blocks = nb;
    for (int i = 0; i < nb; i++) {
        solid_block *b = &g->blocks[i];
        b->section = blocks[i];
        fsi_shape_read(&b->shape, c, b->section, g->spacing);
    }
    g->n_regions = nr;
    for (int i = 0; i < nr; i++) {
        solid_region *r = &g->regions[i];
        r->section = regions[i];
        r->action = action_of(fsi_case_get(c, r->section, "action"));
        read_vector(c, r->section, "min", r->min);
        read_vector(c, r->section, "max", r->max);
        read_vector(c, r->section, "force", r->force);
        r->ramp_time = fsi_case_get_real(c, r->section, "ramp_time", 0.0);
        const char *face = fsi_case_get(c, r->section, "clamp_face");
        r->clamp_face = face ? solid_clamp_face_parse(face) : -1;
        if (r->clamp_face < -1)
            r->clamp_face = -1;     /* refused by the check; an unchecked case gets none */
    }
    g->n_probes = np;
    for (int i = 0; i < np; i++) {
        g->probes[i].section = probes[i];
        read_vector(c, probes[i], "point", g->probes[i].point);
    }
    g->n_cracks = nc;
    for (int i = 0; i < nc; i++) {
        g->cracks[i].section = cracks[i];
        read_vector(c, cracks[i], "from", g->cracks[i].from);
        read_vector(c, cracks[i], "to", g->cracks[i].to);
    }
    free(blocks);
    free(regions);
    free(probes);
    free(cracks);
    return 0;

out_of_memory:
    free(blocks);
    free(regions);
    free(probes);
    free(cracks);
    solid_geometry_free(g);
    snprintf(msg, msg_size, "out of memory reading the solid's geometry");
    return -1;
}

void solid_geometry_free(solid_geometry *g)
{
    free(g->blocks);
    free(g->regions);
    free(g->probes);
    free(g->cracks);
    memset(g, 0, sizeof *g);
}

#if FSI_DIM == 2
/* Twice the signed area of the triangle a, b, c: > 0 when c lies left of a -> b. */
static double orientation(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}
#endif

int solid_crack_cuts(const double *p, const double *q, const double *a, const double *b)
{
#if FSI_DIM == 2
    return orientation(a, b, p) * orientation(a, b, q) < 0.0 &&
           orientation(p, q, a) * orientation(p, q, b) <= 0.0;
#else
    (void)p, (void)q, (void)a, (void)b;
    return 0;
#endif
}

double solid_block_spacings(const solid_block *b, double spacing, int axis)
{
    return (b->shape.max[axis] - b->shape.min[axis]) / spacing;
}

long solid_block_points(const solid_block *b)
{
    return (long)fsi_shape_points(&b->shape);
}

int solid_region_contains(const solid_region *r, double spacing, const double *x)
{
    return fsi_box_contains(r->min, r->max, SOLID_GEOMETRY_TOL * spacing, x);
}

int solid_geometry_removed(const solid_geometry *g, const double *x)
{
    for (int r = 0; r < g->n_regions; r++)
        if (g->regions[r].action == SOLID_REGION_REMOVE &&
            solid_region_contains(&g->regions[r], g->spacing, x))
            return 1;
    return 0;
}

int solid_blocks_overlap(const solid_block *a, const solid_block *b, double spacing)
{
    return fsi_shapes_overlap(&a->shape, &b->shape, spacing);
}

void solid_particles_free(solid_particles *p)
{
    free(p->id);
    free(p->x0);
    free(p->x);
    free(p->v);
    free(p->a);
    free(p->volume);
    free(p->density);
    free(p->flags);
    free(p->block);
    free(p->mirror);
    memset(p, 0, sizeof *p);
}

static int particles_alloc(solid_particles *p, long n)
{
    size_t un = (size_t)n, uv = un * FSI_DIM;
    p->id = malloc(un * sizeof *p->id);
    p->x0 = malloc(uv * sizeof *p->x0);
    p->x = malloc(uv * sizeof *p->x);
    p->v = calloc(uv, sizeof *p->v);
    p->a = calloc(uv, sizeof *p->a);
    p->volume = malloc(un * sizeof *p->volume);
    p->density = malloc(un * sizeof *p->density);
    p->flags = calloc(un, sizeof *p->flags);
    p->block = malloc(un * sizeof *p->block);
    p->mirror = NULL;
    if (!p->id || !p->x0 || !p->x || !p->v || !p->a || !p->volume || !p->density ||
        !p->flags || !p->block) {
        solid_particles_free(p);
        return -1;
    }
    return 0;
}

double solid_geometry_lattice_size(const solid_geometry *g)
{
    double n = 0.0;
    for (int b = 0; b < g->n_blocks; b++)
        n += fsi_shape_points(&g->blocks[b].shape);
    return n;
}

static const char *const clamp_face_words[] = {"x_min", "x_max", "y_min", "y_max",
                                                "z_min", "z_max"};

int solid_clamp_face_parse(const char *word)
{
    if (strcmp(word, "none") == 0)
        return -1;
    for (int k = 0; k < 2 * FSI_DIM; k++)
        if (strcmp(word, clamp_face_words[k]) == 0)
            return k;
    return -2;
}

/* Pairs the points of mirror clamp regions with their images across the clamp face
 * (x_image = 2 plane - x along the face's axis). Returns how many found none, or -1
 * when memory runs out. */
static int pair_mirrored_points(const solid_geometry *g, solid_particles *p)
{
    int any = 0;
    for (int r = 0; r < g->n_regions; r++)
        any |= g->regions[r].action == SOLID_REGION_CLAMP && g->regions[r].clamp_face >= 0;
    if (!any)
        return 0;
    p->mirror = malloc((size_t)p->n * sizeof *p->mirror);
    if (!p->mirror)
        return -1;
    int unpaired = 0;
    for (int i = 0; i < p->n; i++) {
        p->mirror[i] = -1;
        if (!(p->flags[i] & SOLID_CLAMPED))
            continue;
        for (int r = 0; r < g->n_regions && p->mirror[i] < 0; r++) {
            const solid_region *reg = &g->regions[r];
            if (reg->action != SOLID_REGION_CLAMP || reg->clamp_face < 0 ||
                !solid_region_contains(reg, g->spacing, &p->x0[i * FSI_DIM]))
                continue;
            const int axis = reg->clamp_face / 2;
            const double plane = reg->clamp_face % 2 ? reg->max[axis] : reg->min[axis];
            double image[FSI_DIM], dist;
            for (int d = 0; d < FSI_DIM; d++)
                image[d] = p->x0[i * FSI_DIM + d];
            image[axis] = 2.0 * plane - image[axis];
            const int m = solid_nearest_particle(p, image, &dist);
            if (m >= 0 && dist <= SOLID_GEOMETRY_TOL * g->spacing &&
                !(p->flags[m] & SOLID_CLAMPED)) {
                p->mirror[i] = m;
                p->flags[i] |= SOLID_MIRRORED;
            } else {
                unpaired++;
            }
        }
    }
    return unpaired;
}

int solid_geometry_build(const solid_geometry *g, double density, solid_particles *p,
                         int *n_unmirrored, char *msg, size_t msg_size)
{
    memset(p, 0, sizeof *p);
    double x[FSI_DIM];
    if (solid_geometry_lattice_size(g) > SOLID_MAX_LATTICE) {
        snprintf(msg, msg_size, "the blocks hold %.3g lattice points, more than %.3g",
                 solid_geometry_lattice_size(g), (double)SOLID_MAX_LATTICE);
        return -1;
    }
    /* Two passes: count the points that survive removal, then fill. */
    long n = 0;
    fsi_shape_walk w;
    for (int b = 0; b < g->n_blocks; b++) {
        fsi_shape_walk_begin(&w, &g->blocks[b].shape, g->spacing);
        while (fsi_shape_walk_next(&w, x))
            n += !solid_geometry_removed(g, x);
    }
    if (n == 0) {
        snprintf(msg, msg_size, "the solid has no particles (every block is empty or removed)");
        return -1;
    }
    if (particles_alloc(p, n) != 0) {
        snprintf(msg, msg_size, "out of memory for %ld solid particles", n);
        return -1;
    }
    p->n = (int)n;
    p->spacing = g->spacing;
    double volume = pow(g->spacing, FSI_DIM);
    int i = 0;
    for (int b = 0; b < g->n_blocks; b++) {
        fsi_shape_walk_begin(&w, &g->blocks[b].shape, g->spacing);
        while (fsi_shape_walk_next(&w, x)) {
            if (solid_geometry_removed(g, x))
                continue;
            p->id[i] = i;
            for (int d = 0; d < FSI_DIM; d++)
                p->x0[i * FSI_DIM + d] = p->x[i * FSI_DIM + d] = x[d];
            p->volume[i] = volume;
            p->density[i] = density;
            p->block[i] = b;
            for (int r = 0; r < g->n_regions; r++) {
                const solid_region *reg = &g->regions[r];
                if (reg->action == SOLID_REGION_REMOVE ||
                    !solid_region_contains(reg, g->spacing, x))
                    continue;
                p->flags[i] |= reg->action == SOLID_REGION_CLAMP  ? SOLID_CLAMPED
                               : reg->action == SOLID_REGION_LOAD ? SOLID_LOADED
                                                                  : SOLID_UNBREAKABLE;
            }
            i++;
        }
    }
    const int unpaired = pair_mirrored_points(g, p);
    if (unpaired < 0) {
        solid_particles_free(p);
        snprintf(msg, msg_size, "out of memory for the mirror clamp of %d particles", p->n);
        return -1;
    }
    if (n_unmirrored)
        *n_unmirrored = unpaired;
    return 0;
}

int solid_region_select(const solid_geometry *g, int r, const solid_particles *p,
                        int32_t *index)
{
    int n = 0;
    for (int i = 0; i < p->n; i++)
        if (solid_region_contains(&g->regions[r], g->spacing, &p->x0[i * FSI_DIM])) {
            if (index)
                index[n] = i;
            n++;
        }
    return n;
}

int solid_nearest_particle(const solid_particles *p, const double *point, double *distance)
{
    int best = -1;
    double best_d2 = INFINITY;
    for (int i = 0; i < p->n; i++) {
        double d2 = 0.0;
        for (int d = 0; d < FSI_DIM; d++) {
            double e = p->x0[i * FSI_DIM + d] - point[d];
            d2 += e * e;
        }
        if (d2 < best_d2) {
            best_d2 = d2;
            best = i;
        }
    }
    if (distance)
        *distance = best >= 0 ? sqrt(best_d2) : INFINITY;
    return best;
}
