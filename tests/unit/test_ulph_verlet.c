/* Candidate lists with a skin (fluid_solver/ulph/verlet_list.h) give the operators the
 * same neighbours as a fresh grid search:
 *  - after every particle moved less than half the skin, the lists are kept, and each
 *    particle's neighbours in the rows of ulph_operators_update_list are exactly those
 *    within the support of a fresh ulph_operators_update (as a set; the order may
 *    differ), with M equal to round-off;
 *  - only wall particles with no fluid particle within the support are idle (empty
 *    row, ULPH_IDLE_WALL, not counted singular), and some are, far from the water;
 *  - a particle that moved more than half the skin, or another particle count, makes
 *    a rebuild; a non-finite position fails;
 *  - the lists are the same bit for bit on 1 and 2 threads. */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fluid_particles.h"
#include "neighbour_grid.h"
#include "gaussian_kernel.h"
#include "ulph_keys.h"
#include "ulph_operators.h"
#include "verlet_list.h"

#include "unit_check.h"

#if FSI_DIM == 2
#define SIDE 40

/* A repeatable number in [-1, 1) (Park-Miller minimal standard generator). */
static double jitter(unsigned long *state)
{
    *state = *state * 16807UL % 2147483647UL;
    return 2.0 * (double)*state / 2147483647.0 - 1.0;
}

/* A jittered lattice in the unit square: water at x < 0.5 above four rows of floor,
 * walls everywhere else (those far from the water are idle). */
static void make_scene(fluid_particles *p)
{
    const double dx = 1.0 / SIDE;
    unsigned long state = 7;
    if (fluid_particles_alloc(p, SIDE * SIDE, dx) != 0)
        exit(2);
    for (int j = 0, n = 0; j < SIDE; j++)
        for (int i = 0; i < SIDE; i++, n++) {
            p->x[2 * n] = (i + 0.5 + 0.3 * jitter(&state)) * dx;
            p->x[2 * n + 1] = (j + 0.5 + 0.3 * jitter(&state)) * dx;
            p->id[n] = n;
            p->volume[n] = dx * dx;
            p->density[n] = 1000.0;
            p->mass[n] = 1000.0 * dx * dx;
            p->flags[n] = j >= 4 && i < SIDE / 2 ? FLUID_PARTICLE_FLUID : FLUID_PARTICLE_WALL;
        }
}

static int compare_int(const void *a, const void *b)
{
    return *(const int32_t *)a - *(const int32_t *)b;
}

/* Every particle's neighbours within the support from the pair-once rows of ops (a
 * fluid pair in the lower index's row, a boundary pair in the fluid particle's row,
 * walls' full rows), as sorted CSR rows: offset[n + 1], list. */
typedef struct {
    int64_t *offset;
    int32_t *list;
} neighbour_sets;

static void add_pair(neighbour_sets *s, int64_t *fill, int i, int j, int pass)
{
    if (pass == 0)
        s->offset[i + 1]++;
    else
        s->list[fill[i]++] = j;
}

static neighbour_sets expand(const ulph_operators *ops)
{
    const fluid_rows *r = &ops->rows;
    const int n = ops->n;
    neighbour_sets s = {calloc((size_t)n + 1, sizeof(int64_t)), NULL};
    int64_t *fill = calloc((size_t)n + 1, sizeof *fill);
    for (int pass = 0; pass < 2; pass++) {
        if (pass == 1) {
            for (int i = 0; i < n; i++)
                s.offset[i + 1] += s.offset[i];
            memcpy(fill, s.offset, (size_t)n * sizeof *fill);
            s.list = malloc((size_t)(s.offset[n] > 0 ? s.offset[n] : 1) * sizeof *s.list);
        }
        for (int i = 0; i < n; i++) {
            for (int64_t e = r->offset[i]; e < r->fluid_end[i]; e++) {
                add_pair(&s, fill, i, r->pair[e], pass);
                add_pair(&s, fill, r->pair[e], i, pass);
            }
            for (int64_t e = r->split[i]; e < r->boundary_end[i]; e++)
                add_pair(&s, fill, i, r->pair[e], pass);
        }
    }
    for (int i = 0; i < n; i++)
        qsort(s.list + s.offset[i], (size_t)(s.offset[i + 1] - s.offset[i]), sizeof *s.list,
              compare_int);
    free(fill);
    return s;
}

/* Row i of the sets into out; its length. */
static int64_t sorted_row(const neighbour_sets *s, int i, int32_t *out)
{
    const int64_t len = s->offset[i + 1] - s->offset[i];
    memcpy(out, s->list + s->offset[i], (size_t)len * sizeof *out);
    return len;
}

static void test_same_neighbours(void)
{
    fluid_particles p;
    make_scene(&p);
    gaussian_kernel k;
    gaussian_kernel_init(&k, ULPH_KERNEL_H_OVER_DX * p.spacing, ULPH_KERNEL_SUPPORT_FACTOR);
    const double skin = 0.1 * k.support;
    fluid_verlet v;
    fluid_verlet_init(&v);
    CHECK(fluid_verlet_update(&v, &p, k.support, skin) == 1, "first update does not build");
    CHECK(fluid_verlet_update(&v, &p, k.support, skin) == 0, "unmoved particles rebuild");

    /* Every particle (walls too: moving walls) by up to 0.3 skin per axis < skin / 2. */
    unsigned long state = 11;
    for (int c = 0; c < p.n * FSI_DIM; c++)
        p.x[c] += 0.3 * skin * jitter(&state);
    CHECK(fluid_verlet_update(&v, &p, k.support, skin) == 0, "moved < skin / 2: rebuilt");

    ulph_operators from_list, fresh;
    ulph_operators_init(&from_list);
    ulph_operators_init(&fresh);
    fsi_neighbour_grid grid;
    fsi_grid_init(&grid);
    CHECK(fsi_grid_build(&grid, p.x, p.n, k.support) == 0, "grid build failed");
    CHECK(ulph_operators_update(&fresh, &k, &grid, &p) == 0, "fresh operators failed");
    CHECK(ulph_operators_update_list(&from_list, &k, &v, &p, 1) == 0, "list operators failed");
    neighbour_sets sets_list = expand(&from_list), sets_fresh = expand(&fresh);

    int32_t *a = malloc((size_t)p.n * sizeof *a), *b = malloc((size_t)p.n * sizeof *b);
    int idle = 0, bad_idle = 0, bad_rows = 0, bad_m = 0;
    for (int i = 0; i < p.n; i++) {
        const int64_t la = sorted_row(&sets_list, i, a), lb = sorted_row(&sets_fresh, i, b);
        if (from_list.flags[i] & ULPH_IDLE_WALL) {
            idle++;
            int fluid = 0;
            for (int64_t q = 0; q < lb; q++)
                fluid |= p.flags[b[q]] & FLUID_PARTICLE_FLUID;
            bad_idle += la != 0 || fluid || !(p.flags[i] & FLUID_PARTICLE_WALL);
            continue;
        }
        bad_rows += la != lb || memcmp(a, b, (size_t)la * sizeof *a) != 0;
        const double *ma = from_list.shape + (int64_t)i * FSI_MAT_SIZE;
        const double *mb = fresh.shape + (int64_t)i * FSI_MAT_SIZE;
        for (int c = 0; c < FSI_MAT_SIZE; c++)
            bad_m += fabs(ma[c] - mb[c]) > 1e-12 * fsi_mat_norm(mb);
    }
    printf("verlet: %d particles, %d idle walls, %lld pairs from the lists, %lld fresh\n",
           p.n, idle, (long long)from_list.n_pairs, (long long)fresh.n_pairs);
    CHECK(idle > 100, "only %d idle walls", idle);
    CHECK(bad_idle == 0, "%d idle particles are not walls away from the water", bad_idle);
    CHECK(bad_rows == 0, "%d rows differ from a fresh search", bad_rows);
    CHECK(bad_m == 0, "%d entries of M differ from a fresh search", bad_m);
    CHECK(from_list.n_singular == fresh.n_singular, "singular: %d from the lists, %d fresh",
          from_list.n_singular, fresh.n_singular);

    /* Half the skin, another count, a non-finite position. */
    p.x[0] += skin; /* at least 0.7 skin from where it was built */
    CHECK(fluid_verlet_update(&v, &p, k.support, skin) == 1, "moved > skin / 2: kept");
    p.n--;
    CHECK(fluid_verlet_update(&v, &p, k.support, skin) == 1, "another count: kept");
    p.n++;
    p.x[3] = NAN;
    CHECK(fluid_verlet_update(&v, &p, k.support, skin) == -1, "a NaN position accepted");
    p.x[3] = 0.5;

    /* 1 and 2 threads. */
    fluid_verlet two;
    fluid_verlet_init(&two);
    omp_set_num_threads(1);
    fluid_verlet_update(&v, &p, k.support, 2.0 * skin);
    omp_set_num_threads(2);
    fluid_verlet_update(&two, &p, k.support, 2.0 * skin);
    CHECK(v.n == two.n && v.offset[v.n] == two.offset[two.n] &&
              memcmp(v.offset, two.offset, (size_t)(v.n + 1) * sizeof *v.offset) == 0 &&
              memcmp(v.candidate, two.candidate, (size_t)v.offset[v.n] * sizeof *v.candidate) == 0 &&
              memcmp(v.idle, two.idle, (size_t)v.n) == 0,
          "the lists differ between 1 and 2 threads");

    free(a);
    free(b);
    free(sets_list.offset);
    free(sets_list.list);
    free(sets_fresh.offset);
    free(sets_fresh.list);
    fsi_grid_free(&grid);
    fluid_verlet_free(&v);
    fluid_verlet_free(&two);
    ulph_operators_free(&from_list);
    ulph_operators_free(&fresh);
    fluid_particles_free(&p);
}
#endif

int main(void)
{
#if FSI_DIM == 2
    test_same_neighbours();
#endif
    return unit_check_report("test_ulph_verlet");
}
