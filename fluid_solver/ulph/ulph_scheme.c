/* The ULPH scheme behind fluid_scheme.h (000 §2.1, §2.3): one evaluation of the rates
 * is
 *   1. neighbour lists (from candidate lists with a skin, fluid_verlet), shape tensors
 *      M and M^-1 at the current positions with V = m / rho (ulph_operators);
 *   2. pressure of every fluid particle from its density (Tait, 000 Eq. 6);
 *   3. wall particles from the fluid around them (000 Eqs. 50-54, ulph_walls);
 *   4. when a density filter is due (every density_filter_interval steps, 000 Eq. 24
 *      with a first-order correction, density_filter below),
 *      the filtered density, then 2-3 again;
 *   5. continuity and momentum (000 Eqs. 16, 23-28, ulph_momentum). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fluid_phases.h"
#include "fluid_scheme.h"
#include "fluid_step.h"
#include "grow.h"
#include "neighbour_grid.h"
#include "small_tensor.h"
#include "tait_eos.h"
#include "gaussian_kernel.h"
#include "ulph_keys.h"
#include "ulph_momentum.h"
#include "ulph_operators.h"
#include "ghost_walls.h"
#include "wc_predictor_corrector.h"
#include "wc_verlet.h"

/* The phases of one evaluation, timed separately (fluid_scheme_use_timers). */
enum { PHASE_SEARCH, PHASE_OPERATORS, PHASE_STATE, PHASE_WALLS, PHASE_FILTER, PHASE_MOMENTUM,
       N_PHASES };
static const char *const phase_name[N_PHASES] = {
    "rates: neighbour search", "rates: operators", "rates: equation of state",
    "rates: walls", "rates: density filter", "rates: momentum"};

struct fluid_scheme {
    gaussian_kernel kernel;
    tait_eos eos;
    ulph_momentum_params momentum;
    fluid_verlet list;
    double skin;                /* of the candidate lists [m] */
    int rows_stale;             /* the lists were restored: derive the rows again */
    ulph_operators ops;
    ulph_momentum_scratch scratch;
    const unsigned char *free_slip;
    double *velocity_for_viscosity, *filtered, *filter_volume, *density_gradient;
    fluid_step_limits step;     /* h, c0, rho0, mu and the CFL factors */
    long filter_interval;
    int filter_due;
    int tension;
    int capacity; /* particles the scratch arrays hold */
    fluid_wc_integrator integrator; /* 000 Eq. 56 */
    int verlet;                 /* 1: the Verlet integrator instead */
    fluid_wc_verlet verlet_integrator;
    fluid_phases phases;
};

void fluid_scheme_use_timers(fluid_scheme *s, fsi_timers *t)
{
    fluid_phases_use(&s->phases, t, phase_name, N_PHASES);
}

void fluid_scheme_particles_reordered(fluid_scheme *s, const int *sorted, int n, void *scratch)
{
    fluid_verlet_invalidate(&s->list);
    fluid_wc_verlet_permute(&s->verlet_integrator, sorted, n, scratch);
}

/* Room for n particles in the per-particle scratch: the moving boundary set changes
 * size between windows (fluid_boundary.h). 0, or -1 when memory runs out. */
static int reserve(fluid_scheme *s, int n)
{
    if (n <= s->capacity && s->velocity_for_viscosity)
        return 0;
    const size_t cap = fsi_grown_capacity((size_t)n);
    int failed = 0;
    s->velocity_for_viscosity = fsi_grow(s->velocity_for_viscosity,
                                         cap * FSI_DIM * sizeof *s->velocity_for_viscosity, &failed);
    s->filtered = fsi_grow(s->filtered, cap * sizeof *s->filtered, &failed);
    s->filter_volume = fsi_grow(s->filter_volume, cap * sizeof *s->filter_volume, &failed);
    s->density_gradient = fsi_grow(s->density_gradient,
                                   cap * FSI_DIM * sizeof *s->density_gradient, &failed);
    if (failed || ulph_momentum_reserve(&s->scratch, (int)cap) != 0)
        return -1;
    s->capacity = (int)cap;
    return 0;
}

fluid_scheme *fluid_scheme_create(const fsi_case *c, const char *role,
                                  const fluid_properties *props, const fluid_particles *p,
                                  char *msg, size_t msg_size)
{
    fluid_scheme *s = calloc(1, sizeof *s);
    if (!s) {
        snprintf(msg, msg_size, "out of memory for the ULPH scheme");
        return NULL;
    }
    const char *own = fsi_case_solver_section(c, role);    /* [fluid.ulph] */
    const double h_over_dx = fsi_case_get_real(c, own, "smoothing_factor", ULPH_KERNEL_H_OVER_DX);
    const double q = fsi_case_get_real(c, own, "support_factor", ULPH_KERNEL_SUPPORT_FACTOR);
    if (gaussian_kernel_init(&s->kernel, h_over_dx * p->spacing, q) != 0) {
        snprintf(msg, msg_size, "[%s] smoothing_factor, support_factor: no kernel with "
                 "h = %g m and delta / h = %g", own ? own : role, h_over_dx * p->spacing, q);
        free(s);
        return NULL;
    }
    s->eos = (tait_eos){props->density, props->sound_speed, props->tait_exponent};
    s->momentum.viscosity = props->viscosity;
    s->momentum.artificial_viscosity = fsi_case_get_real(c, own, "artificial_viscosity", 0.02);
    s->momentum.h = s->kernel.h;
    const char *viscous = fsi_case_get(c, own, "viscous_operator");
    s->momentum.viscous_laplacian = !viscous || strcmp(viscous, "laplacian") == 0;
    s->momentum.c0 = props->sound_speed;
    s->momentum.rho0 = props->density;
    s->momentum.contact = fsi_case_get_real(c, own, "wall_contact", 0.01);
    s->momentum.spacing = p->spacing;
    memcpy(s->momentum.gravity, props->gravity, sizeof s->momentum.gravity);
    s->free_slip = props->free_slip;
    /* The case check estimates the step with the same limits (fluid_step.h). */
    fluid_step_limits_read(&s->step, c, role);
    s->step.h = s->kernel.h;
    s->step.sound_speed = props->sound_speed;
    s->step.density = props->density;
    s->step.viscosity = props->viscosity;
    s->filter_interval = fsi_case_get_int(c, own, "density_filter_interval", 20);
    s->tension = fsi_case_get_bool(c, own, "tension", 0);
    const char *integrator = fsi_case_get(c, own, "integrator");
    s->verlet = integrator && strcmp(integrator, "verlet") == 0;
    fluid_wc_verlet_init(&s->verlet_integrator, FLUID_VERLET_EULER_INTERVAL);
    s->skin = fsi_case_get_real(c, own, "neighbour_skin", FLUID_VERLET_SKIN) * s->kernel.support;
    fluid_verlet_init(&s->list);
    fsi_grid_set_periodic(&s->list.grid, &props->periodic);
    ulph_operators_init(&s->ops);
    if (reserve(s, p->n) != 0) {
        fluid_scheme_free(s);
        snprintf(msg, msg_size, "out of memory for the ULPH scheme of %d particles", p->n);
        return NULL;
    }
    return s;
}

void fluid_scheme_free(fluid_scheme *s)
{
    if (!s)
        return;
    fluid_verlet_free(&s->list);
    ulph_operators_free(&s->ops);
    ulph_momentum_free(&s->scratch);
    fluid_wc_integrator_free(&s->integrator);
    fluid_wc_verlet_free(&s->verlet_integrator);
    free(s->velocity_for_viscosity);
    free(s->filtered);
    free(s->filter_volume);
    free(s->density_gradient);
    free(s);
}

int fluid_scheme_compressible(const fluid_scheme *s)
{
    (void)s;
    return 1;
}

int fluid_scheme_holds_at_walls(const fluid_scheme *s)
{
    (void)s;
    return 0;   /* the walls' pressure holds the fluid out */
}

double fluid_scheme_pressure(const fluid_scheme *s, double density)
{
    return tait_eos_pressure(&s->eos, density);
}

double fluid_scheme_density(const fluid_scheme *s, double pressure)
{
    return tait_eos_density(&s->eos, pressure);
}

double fluid_scheme_compression_energy(const fluid_scheme *s, double density)
{
    return tait_eos_energy(&s->eos, density);
}

double fluid_scheme_smoothing_length(const fluid_scheme *s)
{
    return s->kernel.h;
}

double fluid_scheme_support(const fluid_scheme *s)
{
    return s->kernel.support;
}

typedef struct {
    const ulph_operators *ops;
    const fluid_particles *p;
    const double *grad;         /* grad rho */
    double *wm, *wv;            /* the sums of the filter */
} filter_context;

/* One side's share: I with neighbour J at x_IJ = rel, kernel w. */
static inline void filter_add(const filter_context *c, int i, int j, double w, const double *rel)
{
    const fluid_particles *p = c->p;
    double shift = 0.0;
    for (int d = 0; d < FSI_DIM; d++)
        shift += c->grad[i * FSI_DIM + d] * rel[d];
    c->wm[i] += w * (p->mass[j] - p->volume[j] * shift);
    c->wv[i] += w * p->volume[j];
}

static void filter_block(void *context, int lo, int hi)
{
    const filter_context *c = context;
    const fluid_rows *r = &c->ops->rows;
    const fluid_particles *p = c->p;
    for (int i = lo; i < hi; i++) {
        if (!(p->flags[i] & FLUID_PARTICLE_FLUID))
            continue;
        for (int64_t e = r->offset[i]; e < r->fluid_end[i]; e++) {
            const int j = r->pair[e];
            double rel[FSI_DIM], back[FSI_DIM];
            ulph_pair_vector(c->ops, p->x, i, j, rel);
            for (int d = 0; d < FSI_DIM; d++)
                back[d] = -rel[d];
            filter_add(c, i, j, r->f[e], rel);
            filter_add(c, j, i, r->f[e], back);
        }
        for (int64_t e = r->split[i]; e < r->boundary_end[i]; e++) {
            const int j = r->pair[e];
            if (!(p->flags[j] & FLUID_PARTICLE_WALL)) /* not the solid's particles */
                continue;
            double rel[FSI_DIM];
            ulph_pair_vector(c->ops, p->x, i, j, rel);
            filter_add(c, i, j, r->f[e], rel);
        }
    }
}

/* 000 Eq. 24, rho_I = sum_J w_IJ m_J / sum_J w_IJ V_J over I and its neighbours (walls
 * included, with the mass of 000 Eq. 54), with a first-order correction:
 *
 *     rho_I = sum_J w_IJ V_J (rho_J - grad rho_I . x_IJ) / sum_J w_IJ V_J
 *
 * (grad rho_I from 000 Eq. 13). Without the correction the Shepard average of a
 * particle whose family is cut by the free surface is taken over deeper, denser
 * particles: in a hydrostatic column (drho/dy = -rho0 g / c0^2) it raises the top row's
 * density by about a spacing's worth, p by ~ rho0 g dx, twice the row's own pressure,
 * and every filter kicks the surface. The corrected average returns any linear density
 * field unchanged (inside, at the surface, at walls) and still removes the
 * lattice-scale noise Eq. 24 is for. */
static void density_filter(fluid_scheme *s, fluid_particles *p)
{
    const int n = p->n;
    const double w0 = gaussian_kernel_w2(&s->kernel, 0.0);
    ulph_gradient_scalar(&s->ops, p, p->density, s->density_gradient);
#pragma omp parallel for schedule(static) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++) {
        s->filtered[i] = w0 * p->mass[i];
        s->filter_volume[i] = w0 * p->volume[i];
    }
    filter_context c = {&s->ops, p, s->density_gradient, s->filtered, s->filter_volume};
    ulph_for_blocks(&s->ops, filter_block, &c);
#pragma omp parallel for schedule(static) if (n >= FLUID_PARALLEL_MIN_PARTICLES)
    for (int i = 0; i < n; i++)
        if (p->flags[i] & FLUID_PARTICLE_FLUID)
            p->density[i] = s->filtered[i] / s->filter_volume[i];
}

int fluid_scheme_rates(fluid_scheme *s, fluid_particles *p, double *drho_dt, double *dv_dt,
                       char *msg, size_t msg_size)
{
    if (reserve(s, p->n) != 0) {
        snprintf(msg, msg_size, "out of memory for the ULPH scheme of %d particles", p->n);
        return -1;
    }
    fluid_phase_start(&s->phases, PHASE_STATE);
    tait_eos_update_fluid(&s->eos, p, s->tension);
    fluid_phase_stop(&s->phases, PHASE_STATE);
    fluid_phase_start(&s->phases, PHASE_SEARCH);
    const int built = fluid_verlet_update(&s->list, p, s->kernel.support, s->skin);
    fluid_phase_stop(&s->phases, PHASE_SEARCH);
    fluid_phase_start(&s->phases, PHASE_OPERATORS);
    const int rc = built < 0 ? -1
                             : ulph_operators_update_list(&s->ops, &s->kernel, &s->list, p,
                                                          built || s->rows_stale);
    fluid_phase_stop(&s->phases, PHASE_OPERATORS);
    if (rc != 0) {
        snprintf(msg, msg_size, "cannot build the neighbour lists of %d particles (a "
                 "position is not finite, or memory ran out)", p->n);
        return -1;
    }
    s->rows_stale = 0;
    fluid_phase_start(&s->phases, PHASE_WALLS);
    ghost_walls_update(&s->ops.rows, &s->ops.periodic, &s->eos, s->momentum.gravity,
                       s->free_slip, p, s->velocity_for_viscosity);
    fluid_phase_stop(&s->phases, PHASE_WALLS);
    if (s->filter_due) {
        fluid_phase_start(&s->phases, PHASE_FILTER);
        density_filter(s, p);
        tait_eos_update_fluid(&s->eos, p, s->tension);
        ghost_walls_update(&s->ops.rows, &s->ops.periodic, &s->eos, s->momentum.gravity,
                           s->free_slip, p, s->velocity_for_viscosity);
        s->filter_due = 0;
        /* The filtered rho^n replaces the step's start; Verlet's leapfrog from rho^{n-1}
         * would bring back the noise it removed, so the next step is the Euler one. */
        fluid_wc_verlet_restart(&s->verlet_integrator);
        fluid_phase_stop(&s->phases, PHASE_FILTER);
    }
    fluid_phase_start(&s->phases, PHASE_MOMENTUM);
    ulph_momentum_rates(&s->ops, &s->momentum, p, s->velocity_for_viscosity, &s->scratch,
                        drho_dt, dv_dt);
    fluid_phase_stop(&s->phases, PHASE_MOMENTUM);
    return 0;
}

int fluid_scheme_step(fluid_scheme *s, fluid_particles *p, double t, double dt,
                      const fluid_step_hooks *hooks, char *msg, size_t msg_size)
{
    if (s->verlet)
        return fluid_wc_verlet_step(&s->verlet_integrator, p, t, dt, hooks, msg, msg_size);
    return fluid_wc_step(&s->integrator, p, t, dt, hooks, msg, msg_size);
}

void fluid_scheme_after_step(fluid_scheme *s, fluid_particles *p, long count)
{
    (void)p;
    /* 000 (after Eq. 24): every twenty steps, to save work and avoid artificial
     * diffusion; applied at the start of the next evaluation, on fresh lists. */
    if (s->filter_interval > 0 && count % s->filter_interval == 0)
        s->filter_due = 1;
}

double fluid_scheme_stable_dt(const fluid_scheme *s, const fluid_particles *p, double amax)
{
    return fluid_stable_step(&s->step, fluid_largest_speed(p), amax);
}

void fluid_scheme_pressure_gradient(const fluid_scheme *s, const fluid_particles *p,
                                    double *grad)
{
    ulph_gradient_scalar(&s->ops, p, p->pressure, grad);
}

void fluid_scheme_boundary_loads(const fluid_scheme *s, const fluid_particles *p,
                                 double *force)
{
    ulph_boundary_loads(&s->ops, &s->momentum, p, s->velocity_for_viscosity, &s->scratch,
                        force);
}

int fluid_scheme_write_fields(const fluid_scheme *s, fsi_h5_writer *out)
{
    const int n = s->ops.n;
    int32_t *flags = malloc((size_t)(n > 0 ? n : 1) * sizeof *flags);
    if (!flags)
        return -1;
    for (int i = 0; i < n; i++)
        flags[i] = s->ops.flags[i] & ULPH_SINGULAR_SHAPE;
    int rc = fsi_h5_write_field_int(out, "singular_shape", flags, 1);
    free(flags);
    return rc;
}

int fluid_scheme_describe_fields(fsi_h5_writer *out)
{
    static const int32_t values[] = {0, ULPH_SINGULAR_SHAPE};
    return fsi_h5_describe(out, "singular_shape", "1",
                           "1 where the particle's shape matrix M could not be inverted, "
                           "so its gradients are zero (docs/ulph.md).") ||
                   fsi_h5_name_flags(out, "singular_shape", FSI_H5_FLAG_VALUES, 2, values,
                                     "regular singular_shape")
               ? -1
               : 0;
}

/* State between steps: the density filter when it is due, the candidate lists (the
 * operators' rows are derived from them again, as after a build), the Verlet
 * integrator's previous state. The predictor-corrector keeps none. */
int fluid_scheme_save_state(const fluid_scheme *s, const fluid_particles *p, fsi_state *st)
{
    const int64_t due = s->filter_due;
    fsi_state_put(st, "ulph.filter_due", &due, sizeof due);
    if (fluid_verlet_save(&s->list, st, "ulph.list") != 0 ||
        fluid_wc_verlet_save(&s->verlet_integrator, p->n, st, "ulph.verlet") != 0)
        return -1;
    return st->failed ? -1 : 0;
}

int fluid_scheme_restore_state(fluid_scheme *s, fluid_particles *p, const fsi_state *st)
{
    (void)p;
    int64_t due;
    if (fsi_state_get(st, "ulph.filter_due", &due, sizeof due) != 0 ||
        fluid_verlet_restore(&s->list, st, "ulph.list") != 0 ||
        fluid_wc_verlet_restore(&s->verlet_integrator, st, "ulph.verlet") != 0)
        return -1;
    s->filter_due = (int)due;
    s->rows_stale = 1;
    return 0;
}

long long fluid_scheme_pair_count(const fluid_scheme *s)
{
    return (long long)s->ops.n_pairs;
}
