/* The solid's side of implicit coupling in the participant library
 * (core/participant_implicit.c, docs/coupling.md "Implicit coupling"):
 *   - the motion given to the fluid ends the window at x_k + u dt and its velocity at
 *     the window's start plus a dt / 2 is u (up to round-off: the end position is
 *     x_k plus a displacement a thousand times smaller, so 1e-10 of the displacement);
 *   - the first iteration's u is the explicit prediction u_prev + a_k dt / 2;
 *   - an end state that matches the motion given converges at once; one that does not
 *     gets the residual |u_out - u_in| / |u_out| computed here apart, and the next
 *     motion differs;
 *   - a linear spring-mass interface with an added-mass response (the fluid's load
 *     -m_a a on a structure of mass m_s < m_a: explicit iteration diverges) converges
 *     with IQN-ILS within 20 iterations to the monolithic answer (1e-8 relative);
 *   - a repeated iteration with other particles than the window's first is refused
 *     with a message naming the checkpoint call. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "dim.h"
#include "participant_implicit.h"
#include "unit_check.h"

#define N 6

/* A [run] section with the acceleration given, read through the case reader as a run
 * reads it; the file goes to $FSI_TEST_TMP (ctest sets it) as other unit tests' do. */
static fsi_case *case_with(const char *acceleration)
{
    const char *dir = getenv("FSI_TEST_TMP") ? getenv("FSI_TEST_TMP") : ".";
    char path[4200];
    snprintf(path, sizeof path, "%s/test_participant_implicit_%s.ini", dir, acceleration);
    mkdir(dir, 0755);   /* ctest's scratch folder; may exist already */
    FILE *f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "cannot write %s\n", path);
        exit(1);
    }
    fprintf(f, "[run]\nend_time = 1\nscheme = implicit\ncoupling_tolerance = 1e-10\n"
               "coupling_acceleration = %s\ncoupling_relaxation = 0.5\n", acceleration);
    fclose(f);
    fsi_case *c = fsi_case_read(path, stderr);
    unlink(path);
    return c;
}

typedef struct {
    int32_t id[N];
    double x[N * FSI_DIM], v[N * FSI_DIM], a[N * FSI_DIM], vol[N], rho[N];
    fsi_interface d;
} state;

static void make_state(state *s)
{
    for (int i = 0; i < N; i++) {
        s->id[i] = 10 + 3 * i;
        s->vol[i] = 1e-4;
        s->rho[i] = 2700.0;
        for (int c = 0; c < FSI_DIM; c++) {
            s->x[i * FSI_DIM + c] = 0.1 * i + 0.01 * c;
            s->v[i * FSI_DIM + c] = 0.2 * sin(i + c);
            s->a[i * FSI_DIM + c] = 3.0 * cos(2 * i + c);
        }
    }
    s->d = (fsi_interface){.n = N, .id = s->id, .position = s->x, .velocity = s->v,
                           .acceleration = s->a, .volume = s->vol, .density = s->rho};
}

/* An implicit solid with the given acceleration (the case is read at init only), and
 * the interface state at the window's start. */
static void start(const char *acceleration, implicit_solid *is, state *s)
{
    fsi_case *c = case_with(acceleration);
    char msg[512];
    CHECK(implicit_solid_init(is, c, msg, sizeof msg) == 0, "init: %s", msg);
    fsi_case_free(c);
    make_state(s);
}

static void check_motion(const implicit_solid *is, const state *s, double dt)
{
    double worst = 0.0;
    for (int k = 0; k < N * FSI_DIM; k++) {
        const double end = s->x[k] + is->v_sent[k] * dt + 0.5 * is->a_sent[k] * dt * dt;
        const double want = s->x[k] + is->u_in[k] * dt;
        worst = fmax(worst, fabs(end - want) / fmax(fabs(is->u_in[k] * dt), 1e-30));
        worst = fmax(worst, fabs(is->v_sent[k] + 0.5 * dt * is->a_sent[k] - is->u_in[k]) /
                                fmax(fabs(is->u_in[k]), 1e-30));
    }
    CHECK(worst < 1e-10, "the motion given ends where u says: worst relative error %g", worst);
}

/* The solid's answer: positions after dt with the mean velocity u_out. */
static void end_state(const state *s, const double *u_out, double dt, double *x_end,
                      fsi_interface *end)
{
    for (int k = 0; k < N * FSI_DIM; k++)
        x_end[k] = s->x[k] + u_out[k] * dt;
    *end = (fsi_interface){.n = N, .id = (int32_t *)s->id, .position = x_end};
}

static void test_motion_and_verdict(void)
{
    implicit_solid is;
    state s;
    start("constant", &is, &s);
    char msg[512];
    const double dt = 1e-3, dt_prev = 8e-4;
    CHECK(implicit_solid_motion(&is, 0, dt, dt_prev, &s.d, msg, sizeof msg) == 0, "%s", msg);
    double worst = 0.0;
    for (int k = 0; k < N * FSI_DIM; k++)
        worst = fmax(worst, fabs(is.u_in[k] - (s.v[k] + 0.5 * dt * s.a[k])));
    CHECK(worst < 1e-15, "first iteration's u is u_prev + a dt / 2 (off by %g)", worst);
    check_motion(&is, &s, dt);

    /* The solid moved exactly as the fluid was told: converged in iteration 0. */
    double x_end[N * FSI_DIM], u[N * FSI_DIM];
    fsi_interface end;
    memcpy(u, is.u_in, sizeof u);
    end_state(&s, u, dt, x_end, &end);
    CHECK(implicit_solid_window_end(&is, &end, msg, sizeof msg) == 0, "%s", msg);
    CHECK(is.verdict.converged == 1, "the motion as given converges (residual %g)",
          is.verdict.displacement_residual);

    /* Iteration 1: the solid went 1 % further; residual 0.01 / 1.01. */
    CHECK(implicit_solid_motion(&is, 1, dt, dt_prev, &s.d, msg, sizeof msg) == 0, "%s", msg);
    for (int k = 0; k < N * FSI_DIM; k++)
        u[k] = 1.01 * is.u_in[k];
    end_state(&s, u, dt, x_end, &end);
    CHECK(implicit_solid_window_end(&is, &end, msg, sizeof msg) == 0, "%s", msg);
    CHECK(!is.verdict.converged, "a 1 %% departure does not converge");
    CHECK(fabs(is.verdict.displacement_residual - 0.01 / 1.01) < 1e-9,
          "displacement residual %.12g, expected %.12g", is.verdict.displacement_residual,
          0.01 / 1.01);
    /* Constant relaxation 0.5: halfway to the output. */
    worst = 0.0;
    for (int k = 0; k < N * FSI_DIM; k++)
        worst = fmax(worst, fabs(is.u_next[k] - 1.005 * is.u_in[k]) / fabs(is.u_in[k]));
    CHECK(worst < 1e-12, "constant relaxation 0.5 goes halfway (off by %g)", worst);

    /* A repeated iteration with a particle less is refused. */
    s.d.n = N - 1;
    CHECK(implicit_solid_motion(&is, 2, dt, dt_prev, &s.d, msg, sizeof msg) != 0 &&
              strstr(msg, "fsi_requires_reading_checkpoint"),
          "another particle set in a repeated iteration is refused: %s", msg);
    implicit_solid_free(&is);
}

/* Added mass: a structure of mass m_s under a fluid that answers its acceleration a
 * with -m_a a, and a spring k; over one window the structure's displacement under a held
 * load F is d = (F + f0) dt^2 / (2 m_s) (from rest, no spring for clarity), and the load
 * for a motion of mean velocity u (acceleration 2 u / dt from rest) is F = -m_a 2 u / dt.
 * The monolithic answer: u = f0 dt / (2 (m_s + m_a)). With m_a / m_s = 5 the plain
 * iteration multiplies the error by -5 each time. */
static void test_added_mass(void)
{
    implicit_solid is;
    state s;
    start("iqn_ils", &is, &s);
    char msg[512];
    for (int k = 0; k < N * FSI_DIM; k++)
        s.v[k] = s.a[k] = 0.0;
    const double dt = 1e-3, m_s = 1.0, ratio[N] = {5, 2, 8, 0.5, 3, 6};
    double x_end[N * FSI_DIM], u_out[N * FSI_DIM];
    fsi_interface end;
    int converged_at = -1;
    for (int it = 0; it < 30 && converged_at < 0; it++) {
        CHECK(implicit_solid_motion(&is, it, dt, dt, &s.d, msg, sizeof msg) == 0, "%s", msg);
        for (int i = 0; i < N; i++)
            for (int d = 0; d < FSI_DIM; d++) {
                const int k = i * FSI_DIM + d;
                const double f0 = 1.0 + i + d;
                const double load = -ratio[i] * m_s * 2.0 * is.u_in[k] / dt;
                u_out[k] = (load + f0) * dt / (2.0 * m_s);
                is.force[k] = load;
            }
        end_state(&s, u_out, dt, x_end, &end);
        CHECK(implicit_solid_window_end(&is, &end, msg, sizeof msg) == 0, "%s", msg);
        if (is.verdict.converged)
            converged_at = it;
    }
    CHECK(converged_at >= 0 && converged_at < 20, "IQN-ILS converges within 20 iterations "
          "(converged at %d)", converged_at);
    double worst = 0.0;
    for (int i = 0; i < N; i++)
        for (int d = 0; d < FSI_DIM; d++) {
            const double f0 = 1.0 + i + d, exact = f0 * dt / (2.0 * m_s * (1.0 + ratio[i]));
            worst = fmax(worst, fabs(u_out[i * FSI_DIM + d] - exact) / exact);
        }
    CHECK(worst < 1e-8, "the monolithic answer to %g relative", worst);
    printf("added mass ratios 0.5 to 8: IQN-ILS converged at iteration %d, error %.2g\n",
           converged_at, worst);
    implicit_solid_free(&is);
}

/* The motion sent depends on the window's length and the last window's (the
 * acceleration 2 (u - u_prev) / (dt + dt_prev)), so the secant history is dropped when
 * either changes (history_restarted bit 2): window 1 follows the zero-length window 0,
 * so window 2 starts afresh; equal windows keep it; a window cut short drops it again,
 * and so do the next two (whose predecessor, and whose history's predecessor, was
 * short). */
static void test_history_and_window_lengths(void)
{
    implicit_solid is;
    state s;
    start("iqn_ils", &is, &s);
    char msg[512];
    const double dts[][2] = {{2e-4, 0}, {2e-4, 2e-4}, {2e-4, 2e-4}, {1e-4, 2e-4},
                             {2e-4, 1e-4}, {2e-4, 2e-4}, {2e-4, 2e-4}};
    const int expected[] = {0, 2, 0, 2, 2, 2, 0};
    for (int w = 0; w < 7; w++) {
        CHECK(implicit_solid_motion(&is, 0, dts[w][0], dts[w][1], &s.d, msg, sizeof msg) == 0,
              "%s", msg);
        CHECK(is.restarted == expected[w], "window %d (dt %g after %g): history_restarted %d, "
              "expected %d", w + 1, dts[w][0], dts[w][1], is.restarted, expected[w]);
        double x_end[N * FSI_DIM];
        fsi_interface end;
        for (int k = 0; k < N * FSI_DIM; k++)
            is.force[k] = 0.0;
        end_state(&s, is.u_in, dts[w][0], x_end, &end);
        CHECK(implicit_solid_window_end(&is, &end, msg, sizeof msg) == 0, "%s", msg);
    }
    implicit_solid_free(&is);
}

int main(void)
{
    test_motion_and_verdict();
    test_added_mass();
    test_history_and_window_lengths();
    return unit_check_report("test_participant_implicit");
}
