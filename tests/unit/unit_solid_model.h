/* Helpers of the solid model unit tests (test_nosbpd_*.c, test_pseudo_spring_*.c):
 * cases written to a scratch file, the model made from one, an internal-force call
 * with error reporting, lattice indices and a small random generator. Header-only
 * (static functions) because every test is one executable; the model is whichever
 * the test links (tests/CMakeLists.txt). */
#ifndef FSI_UNIT_SOLID_MODEL_H
#define FSI_UNIT_SOLID_MODEL_H

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "case_file.h"
#include "geometry.h"
#include "small_tensor.h"
#include "solid_model.h"
#include "solid_particles.h"

#include "unit_check.h"
#include "unit_solid_lattice.h"

/* A case from INI text (not validated: the model falls back to its defaults). */
static inline fsi_case *test_case(const char *text)
{
    const char *dir = getenv("FSI_TEST_TMP");
    if (!dir || !*dir)
        dir = "/tmp";
    if (mkdir(dir, 0777) != 0 && errno != EEXIST)
        dir = "/tmp";
    char path[512];
    snprintf(path, sizeof path, "%s/solid_case_%ld.ini", dir, (long)getpid());
    FILE *f = fopen(path, "w");
    if (!f) {
        printf("cannot write %s\n", path);
        exit(2);
    }
    fputs(text, f);
    fclose(f);
    fsi_case *c = fsi_case_read(path, stderr);
    remove(path);
    if (!c) {
        printf("cannot read the test case:\n%s\n", text);
        exit(2);
    }
    return c;
}

/* Lattice index of a point along axis d. */
static inline int test_index(const solid_particles *p, int i, int d)
{
    return (int)floor(p->x0[i * FSI_DIM + d] / p->spacing);
}

/* Distance (in spacings, counted in whole points) from point i to the nearest edge
 * of an nx x ny lattice: 0 for the outermost layer. */
static inline int test_depth(const solid_particles *p, int i, const int *n_per_axis)
{
    int depth = 1 << 30;
    for (int d = 0; d < FSI_DIM; d++) {
        const int a = test_index(p, i, d);
        const int e = a < n_per_axis[d] - 1 - a ? a : n_per_axis[d] - 1 - a;
        depth = e < depth ? e : depth;
    }
    return depth;
}

static unsigned long long test_rng = 0x9E3779B97F4A7C15ULL;

static inline double test_uniform(void)
{
    test_rng ^= test_rng << 13;
    test_rng ^= test_rng >> 7;
    test_rng ^= test_rng << 17;
    return (double)(test_rng >> 11) / 9007199254740992.0;
}

static inline solid_model *test_model(const char *case_text, const solid_particles *p)
{
    fsi_case *c = test_case(case_text);
    char msg[512];
    solid_model *m = solid_model_create(c, p, msg, sizeof msg);
    fsi_case_free(c);
    if (!m) {
        printf("solid_model_create failed: %s\n", msg);
        exit(2);
    }
    return m;
}

/* internal force with error reporting; returns the call's status. */
static inline int test_force(solid_model *m, const solid_particles *p, const double *x_prev,
                      double *force)
{
    char msg[512];
    const int rc = solid_model_internal_force(m, p, x_prev, 1e-6, 0.0, force, msg, sizeof msg);
    if (rc != 0)
        printf("internal force: %s\n", msg);
    return rc;
}

#endif
