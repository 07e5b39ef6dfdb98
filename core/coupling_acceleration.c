/* Constant, Aitken and IQN-ILS acceleration of a coupling window's fixed point
 * (core/coupling_acceleration.h). */
#include "coupling_acceleration.h"

#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grow.h"

struct fsi_accel {
    fsi_accel_settings s;
    int n, ncomp, m;              /* this window's; n = -1 before the first window */
    int32_t *id;                  /* this window's ids */
    int in_window, iteration;     /* iteration: fsi_accel_next calls in this window */
    int windows;                  /* accepted windows so far: the current one's tag */
    double omega;                 /* the factor last used */
    /* Capacities: values per vector, ids, columns (IQN-ILS; 0 for the others). */
    size_t capacity_m;
    int capacity_n, capacity_columns;
    double *r, *r_prev, *xt_prev; /* m values each */
    /* IQN-ILS: column j of V, W and Q at j m, newest first; window_of[j] the window
     * it was taken in; R column-major with leading dimension capacity_columns. */
    int columns;
    double *v, *w, *q, *rr, *alpha;
    int *window_of;
};

static double dot(const double *u, const double *v, int m)
{
    double s = 0.0;
    for (int i = 0; i < m; i++)
        s += u[i] * v[i];
    return s;
}

fsi_accel *fsi_accel_create(const fsi_accel_settings *s, char *msg, size_t msg_size)
{
    const char *why = NULL;
    if (!s)
        why = "no settings";
    else if (s->kind != FSI_ACCEL_CONSTANT && s->kind != FSI_ACCEL_AITKEN &&
             s->kind != FSI_ACCEL_IQN_ILS)
        why = "unknown acceleration kind";
    else if (!(s->omega0 > 0.0 && s->omega0 <= 1.0))
        why = "omega0 must be in (0, 1]";
    else if (s->reuse_windows < 0)
        why = "reuse_windows must be >= 0";
    else if (s->kind == FSI_ACCEL_IQN_ILS && s->max_columns < 1)
        why = "max_columns must be >= 1 for IQN-ILS";
    else if (s->kind == FSI_ACCEL_IQN_ILS && !(s->filter_eps >= 0.0 && s->filter_eps < 1.0))
        why = "filter_eps must be in [0, 1) for IQN-ILS";
    fsi_accel *a = why ? NULL : calloc(1, sizeof *a);
    if (!why && !a)
        why = "out of memory";
    if (why) {
        if (msg && msg_size)
            snprintf(msg, msg_size, "coupling acceleration: %s", why);
        return NULL;
    }
    a->s = *s;
    a->n = -1;
    a->omega = s->omega0;
    return a;
}

/* Keeps the first 'keep' columns (the newest) and drops the rest. */
static void truncate_columns(fsi_accel *a, int keep)
{
    if (keep < a->columns)
        a->columns = keep;
}

/* Removes column j from V, W and their tags (Q and R are rebuilt before use). */
static void remove_column(fsi_accel *a, int j)
{
    const size_t m = (size_t)a->m, after = (size_t)(a->columns - j - 1);
    memmove(a->v + j * m, a->v + (j + 1) * m, after * m * sizeof *a->v);
    memmove(a->w + j * m, a->w + (j + 1) * m, after * m * sizeof *a->w);
    memmove(a->window_of + j, a->window_of + j + 1, after * sizeof *a->window_of);
    a->columns--;
}

/* Room for m values per vector, n ids and, for IQN-ILS, the columns: at most
 * max_columns, and never more than m + 1 (the filter leaves at most m independent
 * ones, plus the newest before it is filtered). Grown only: a smaller window keeps
 * the memory. 0, or -1 with the capacities unchanged. */
static int reserve(fsi_accel *a, int n, size_t m)
{
    size_t cols = 0;
    if (a->s.kind == FSI_ACCEL_IQN_ILS)
        cols = m + 1 < (size_t)a->s.max_columns ? m + 1 : (size_t)a->s.max_columns;
    const size_t vec = (m > 0 ? m : 1) * sizeof(double);
    if (cols > SIZE_MAX / 2 / vec)
        return -1;
    int failed = 0;
    if ((size_t)n > (size_t)a->capacity_n) {
        a->id = fsi_grow(a->id, (size_t)n * sizeof *a->id, &failed);
        if (!failed)
            a->capacity_n = n;
    }
    if (m > a->capacity_m || (int)cols > a->capacity_columns) {
        a->r = fsi_grow(a->r, vec, &failed);
        a->r_prev = fsi_grow(a->r_prev, vec, &failed);
        a->xt_prev = fsi_grow(a->xt_prev, vec, &failed);
        if (cols > 0) {
            a->v = fsi_grow(a->v, cols * vec, &failed);
            a->w = fsi_grow(a->w, cols * vec, &failed);
            a->q = fsi_grow(a->q, cols * vec, &failed);
            a->rr = fsi_grow(a->rr, cols * cols * sizeof *a->rr, &failed);
            a->alpha = fsi_grow(a->alpha, cols * sizeof *a->alpha, &failed);
            a->window_of = fsi_grow(a->window_of, cols * sizeof *a->window_of, &failed);
        }
        if (failed)
            return -1;
        a->capacity_m = m;
        a->capacity_columns = (int)cols;
    }
    return failed ? -1 : 0;
}

int fsi_accel_begin_window(fsi_accel *a, int n, int ncomp, const int32_t *id)
{
    if (a->in_window) {
        /* The last window was repeated, not accepted: its columns (the newest) are not
         * kept. */
        while (a->columns > 0 && a->window_of[0] == a->windows)
            remove_column(a, 0);
        a->in_window = 0;
    }
    if (n < 0 || ncomp < 1 || n > INT_MAX / ncomp || (n > 0 && !id))
        return -1;
    const int changed = a->n >= 0 && (n != a->n || ncomp != a->ncomp ||
                                      (n > 0 && memcmp(id, a->id, (size_t)n * sizeof *id)));
    if (reserve(a, n, (size_t)n * (size_t)ncomp) != 0)
        return -1;
    if (changed || a->n < 0)
        a->columns = 0;
    if (n > 0)
        memcpy(a->id, id, (size_t)n * sizeof *id);
    a->n = n;
    a->ncomp = ncomp;
    a->m = n * ncomp;
    a->iteration = 0;
    a->in_window = 1;
    a->omega = a->s.omega0;
    return changed;
}

void fsi_accel_drop_history(fsi_accel *a)
{
    if (!a->in_window)
        a->columns = 0;
}

void fsi_accel_end_window(fsi_accel *a)
{
    if (!a->in_window)
        return;
    a->in_window = 0;
    a->windows++;
    /* Tags do not rise along the columns (newest first), so the windows too old to be
     * reused are a tail. */
    int keep = 0;
    while (keep < a->columns && a->windows - a->window_of[keep] <= a->s.reuse_windows)
        keep++;
    truncate_columns(a, keep);
}

static void relax(const double *x_in, const double *r, double omega, int m, double *x_next)
{
    for (int i = 0; i < m; i++)
        x_next[i] = x_in[i] + omega * r[i];
}

/* Aitken's factor from the last two residuals (Kuttler & Wall 2008): the secant
 * estimate of the scalar relaxation that would have zeroed r along r_i - r_{i-1}. */
static double aitken_omega(const fsi_accel *a)
{
    double dd = 0.0, rd = 0.0;
    for (int i = 0; i < a->m; i++) {
        const double d = a->r[i] - a->r_prev[i];
        dd += d * d;
        rd += a->r_prev[i] * d;
    }
    const double omega = -a->omega * rd / dd;
    return dd > 0.0 && isfinite(omega) ? omega : a->omega;
}

/* The newest column: r_i - r_{i-1} and xt_i - xt_{i-1}, in front of the others;
 * when all places are taken the oldest goes. */
static void insert_column(fsi_accel *a, const double *xt)
{
    const size_t m = (size_t)a->m;
    truncate_columns(a, a->capacity_columns - 1);
    memmove(a->v + m, a->v, (size_t)a->columns * m * sizeof *a->v);
    memmove(a->w + m, a->w, (size_t)a->columns * m * sizeof *a->w);
    memmove(a->window_of + 1, a->window_of, (size_t)a->columns * sizeof *a->window_of);
    for (size_t i = 0; i < m; i++) {
        a->v[i] = a->r[i] - a->r_prev[i];
        a->w[i] = xt[i] - a->xt_prev[i];
    }
    a->window_of[0] = a->windows;
    a->columns++;
}

/* V = Q R by modified Gram-Schmidt, newest column first, each column orthogonalised
 * twice against the kept ones: one pass loses orthogonality in proportion to the
 * condition of V, a second restores it to round-off ("twice is enough", Kahan, in
 * Parlett, The Symmetric Eigenvalue Problem, 1980). A column left with less than
 * filter_eps of its norm lies (nearly) in the span of the newer ones: it is removed
 * from V and W for good (the QR2 filter of Haelterman et al. 2016); keeping it would
 * make R nearly singular and alpha large and dominated by round-off. */
static void factor_and_filter(fsi_accel *a)
{
    const int m = a->m, ld = a->capacity_columns;
    int j = 0;
    while (j < a->columns) {
        double *qj = a->q + (size_t)j * m, *rj = a->rr + (size_t)j * ld;
        memcpy(qj, a->v + (size_t)j * m, (size_t)m * sizeof *qj);
        const double before = sqrt(dot(qj, qj, m));
        for (int k = 0; k < j; k++)
            rj[k] = 0.0;
        for (int pass = 0; pass < 2; pass++)
            for (int k = 0; k < j; k++) {
                const double *qk = a->q + (size_t)k * m;
                const double c = dot(qk, qj, m);
                rj[k] += c;
                for (int i = 0; i < m; i++)
                    qj[i] -= c * qk[i];
            }
        const double after = sqrt(dot(qj, qj, m));
        if (!(after > a->s.filter_eps * before) || !(after > 0.0)) {
            remove_column(a, j);
            continue;
        }
        rj[j] = after;
        for (int i = 0; i < m; i++)
            qj[i] /= after;
        j++;
    }
}

/* x_next = xt + W alpha with R alpha = -Q^T r, the least-squares solution of
 * min |V alpha + r| (Degroote et al. 2009). */
static void quasi_newton(fsi_accel *a, const double *xt, double *x_next)
{
    const int m = a->m, k = a->columns, ld = a->capacity_columns;
    for (int j = 0; j < k; j++)
        a->alpha[j] = -dot(a->q + (size_t)j * m, a->r, m);
    for (int j = k - 1; j >= 0; j--) {
        double s = a->alpha[j];
        for (int l = j + 1; l < k; l++)
            s -= a->rr[j + (size_t)l * ld] * a->alpha[l];
        a->alpha[j] = s / a->rr[j + (size_t)j * ld];
    }
    memcpy(x_next, xt, (size_t)m * sizeof *x_next);
    for (int j = 0; j < k; j++) {
        const double *wj = a->w + (size_t)j * m;
        for (int i = 0; i < m; i++)
            x_next[i] += a->alpha[j] * wj[i];
    }
}

int fsi_accel_next(fsi_accel *a, const double *x_in, const double *x_out, double *x_next)
{
    if (!a->in_window)
        return -1;
    const int m = a->m;
    for (int i = 0; i < m; i++)
        a->r[i] = x_out[i] - x_in[i];
    switch (a->s.kind) {
    case FSI_ACCEL_CONSTANT:
        relax(x_in, a->r, a->omega, m, x_next);
        break;
    case FSI_ACCEL_AITKEN:
        if (a->iteration > 0)
            a->omega = aitken_omega(a);
        relax(x_in, a->r, a->omega, m, x_next);
        break;
    case FSI_ACCEL_IQN_ILS:
        if (a->iteration > 0)
            insert_column(a, x_out);
        factor_and_filter(a);
        if (a->columns > 0) {
            quasi_newton(a, x_out, x_next);
            a->omega = 0.0;
        } else {
            a->omega = a->s.omega0;
            relax(x_in, a->r, a->omega, m, x_next);
        }
        memcpy(a->xt_prev, x_out, (size_t)m * sizeof *x_out);
        break;
    }
    memcpy(a->r_prev, a->r, (size_t)m * sizeof *a->r);
    a->iteration++;
    return 0;
}

int fsi_accel_columns(const fsi_accel *a)
{
    return a->columns;
}

double fsi_accel_last_omega(const fsi_accel *a)
{
    return a->omega;
}

void fsi_accel_free(fsi_accel *a)
{
    if (!a)
        return;
    free(a->id);
    free(a->r);
    free(a->r_prev);
    free(a->xt_prev);
    free(a->v);
    free(a->w);
    free(a->q);
    free(a->rr);
    free(a->alpha);
    free(a->window_of);
    free(a);
}

/* The counters and sizes, one entry. */
typedef struct {
    int n, ncomp, m, in_window, iteration, windows, columns, capacity_n, capacity_columns;
    size_t capacity_m;
    double omega;
} saved_counters;

enum { ARRAY_FIELDS = 7 };

/* The arrays of a as fields "<prefix><array>" (names in names[ARRAY_FIELDS][64]),
 * sized by its current counters. */
static int array_fields(fsi_accel *a, const char *prefix, char names[][64], fsi_state_field *f)
{
    const size_t m = a->m > 0 ? (size_t)a->m : 0, cols = (size_t)a->columns;
    const struct {
        const char *what;
        void *data;
        size_t bytes;
    } t[ARRAY_FIELDS] = {{"id", a->id, a->n > 0 ? (size_t)a->n * sizeof *a->id : 0},
                         {"r", a->r, m * sizeof(double)},
                         {"r_prev", a->r_prev, m * sizeof(double)},
                         {"xt_prev", a->xt_prev, m * sizeof(double)},
                         {"v", a->v, cols * m * sizeof(double)},
                         {"w", a->w, cols * m * sizeof(double)},
                         {"window_of", a->window_of, cols * sizeof(int)}};
    for (int k = 0; k < ARRAY_FIELDS; k++) {
        snprintf(names[k], 64, "%s%s", prefix, t[k].what);
        f[k] = (fsi_state_field){names[k], t[k].data, t[k].data ? t[k].bytes : 0};
    }
    return ARRAY_FIELDS;
}

int fsi_accel_save(const fsi_accel *a, fsi_state *st, const char *prefix)
{
    char names[ARRAY_FIELDS + 1][64];
    fsi_state_field f[ARRAY_FIELDS + 1];
    saved_counters c = {a->n,       a->ncomp,   a->m,       a->in_window,
                        a->iteration, a->windows, a->columns, a->capacity_n,
                        a->capacity_columns, a->capacity_m, a->omega};
    snprintf(names[ARRAY_FIELDS], 64, "%scounters", prefix);
    f[ARRAY_FIELDS] = (fsi_state_field){names[ARRAY_FIELDS], &c, sizeof c};
    /* The arrays are only read here. */
    array_fields((fsi_accel *)a, prefix, names, f);
    return fsi_state_put_fields(st, f, ARRAY_FIELDS + 1);
}

int fsi_accel_restore(fsi_accel *a, const fsi_state *st, const char *prefix)
{
    char name[64], names[ARRAY_FIELDS][64];
    saved_counters c;
    snprintf(name, sizeof name, "%scounters", prefix);
    if (fsi_state_get(st, name, &c, sizeof c) != 0)
        return -1;
    /* The capacities as they were: how many columns fit decides which go first. */
    if ((c.capacity_n > 0 || c.capacity_m > 0) && reserve(a, c.capacity_n, c.capacity_m) != 0)
        return -1;
    a->n = c.n;
    a->ncomp = c.ncomp;
    a->m = c.m;
    a->in_window = c.in_window;
    a->iteration = c.iteration;
    a->windows = c.windows;
    a->columns = c.columns;
    a->omega = c.omega;
    fsi_state_field f[ARRAY_FIELDS];
    return fsi_state_get_fields(st, f, array_fields(a, prefix, names, f));
}
