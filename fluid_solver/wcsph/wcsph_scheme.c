/* The WCSPH scheme behind fluid_scheme.h (004 §2, docs/wcsph.md): one evaluation of the
 * rates is
 *   1. pressure and volume of every fluid particle from its density (Tait, 004 Eq. 4);
 *   2. the Verlet candidates (neighbours/verlet_list.h) and, at each of their builds,
 *      the scheme's rows (fluid_rows.h: each fluid pair once); the pairs of the rows
 *      now within the support and their kernel gradients;
 *   3. the dummy wall particles, and the solid's particles when they are dummies, from
 *      the fluid around them (004 Eqs. 10-11, walls/ghost_walls.h);
 *   4. sound speed, viscous stress and renormalised density gradient (wcsph_gradients);
 *   5. continuity with density diffusion and momentum (004 Eqs. 6-9, wcsph_rates).
 * with the Wendland C2 kernel (004 Eq. 5).
 * Steps with the shared predictor-corrector (004 §4) or the Verlet scheme. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fluid_phases.h"
#include "fluid_scheme.h"
#include "fluid_parallel.h"
#include "fluid_step.h"
#include "grow.h"
#include "small_tensor.h"
#include "tait_eos.h"
#include "wc_predictor_corrector.h"
#include "wc_verlet.h"
#include "wcsph_keys.h"
#include "wcsph_rates.h"
#include "wendland_c2.h"

enum { PHASE_SEARCH, PHASE_ROWS, PHASE_STATE, PHASE_WALLS, PHASE_GRADIENTS, PHASE_MOMENTUM,
       N_PHASES };
static const char *const phase_name[N_PHASES] = {
    "rates: neighbour search", "rates: pairs", "rates: equation of state", "rates: walls",
    "rates: gradients", "rates: momentum"};

struct fluid_scheme {
    wendland_c2_kernel kernel;
    tait_eos eos;
    wcsph_params prm;
    fluid_verlet list;
    double skin;                /* of the candidate lists [m] */
    int rows_stale;             /* the lists were restored: derive the rows again */
    fluid_rows rows;
    wcsph_scratch scratch;
    const unsigned char *free_slip;
    double *velocity_for_viscosity;
    int capacity;
    fluid_step_limits step;
    int verlet;                 /* 1: the Verlet integrator */
    fluid_wc_integrator predictor_corrector;
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

static int reserve(fluid_scheme *s, int n)
{
    if (n <= s->capacity && s->velocity_for_viscosity)
        return 0;
    const size_t cap = fsi_grown_capacity((size_t)n);
    int failed = 0;
    s->velocity_for_viscosity = fsi_grow(s->velocity_for_viscosity,
                                         cap * FSI_DIM * sizeof *s->velocity_for_viscosity,
                                         &failed);
    if (failed || wcsph_scratch_reserve(&s->scratch, (int)cap) != 0)
        return -1;
    s->capacity = (int)cap;
    return 0;
}

fluid_scheme *fluid_scheme_create(const fsi_case *c, const char *role,
                                  const fluid_properties *props, const fluid_particles *p,
                                  char *msg, size_t msg_size)
{
    const char *own = fsi_case_solver_section(c, role);    /* [fluid.wcsph] */
    fluid_scheme *s = calloc(1, sizeof *s);
    if (!s) {
        snprintf(msg, msg_size, "out of memory for the WCSPH scheme");
        return NULL;
    }
    const double h_over_dx = fsi_case_get_real(c, own, "smoothing_factor", WCSPH_H_OVER_DX);
    if (wendland_c2_init(&s->kernel, h_over_dx * p->spacing) != 0) {
        snprintf(msg, msg_size, "[%s] smoothing_factor: no kernel with h = %g m", own,
                 h_over_dx * p->spacing);
        free(s);
        return NULL;
    }
    s->eos = (tait_eos){props->density, props->sound_speed, props->tait_exponent};
    wcsph_params *prm = &s->prm;
    prm->h = s->kernel.h;
    prm->c0 = props->sound_speed;
    prm->rho0 = props->density;
    prm->gamma = props->tait_exponent;
    prm->viscosity = props->viscosity;
    prm->beta1 = fsi_case_get_real(c, own, "artificial_viscosity", WCSPH_ARTIFICIAL_VISCOSITY);
    prm->beta2 = fsi_case_get_real(c, own, "artificial_viscosity_quadratic", 0.0);
    prm->delta = fsi_case_get_real(c, own, "density_diffusion", WCSPH_DENSITY_DIFFUSION);
    prm->antuono = fsi_case_choice_is(c, own, "density_diffusion_form", "antuono");
    prm->laplacian = fsi_case_choice_is(c, own, "viscous_operator", "laplacian");
    prm->solid_dummy = !fsi_case_choice_is(c, own, "solid_coupling", "contact");
    prm->contact = fsi_case_get_real(c, own, "solid_contact", WCSPH_SOLID_CONTACT);
    prm->spacing = p->spacing;
    memcpy(prm->gravity, props->gravity, sizeof prm->gravity);
    s->free_slip = props->free_slip;
    fluid_step_limits_read(&s->step, c, role);
    s->step.h = s->kernel.h;
    s->step.sound_speed = props->sound_speed;
    s->step.density = props->density;
    s->step.viscosity = props->viscosity;
    s->verlet = fsi_case_choice_is(c, own, "integrator", "verlet");
    fluid_wc_verlet_init(&s->verlet_integrator, FLUID_VERLET_EULER_INTERVAL);
    s->skin = fsi_case_get_real(c, own, "neighbour_skin", FLUID_VERLET_SKIN) * s->kernel.support;
    fluid_verlet_init(&s->list);
    fsi_grid_set_periodic(&s->list.grid, &props->periodic);
    fluid_rows_init(&s->rows);
    if (reserve(s, p->n) != 0) {
        fluid_scheme_free(s);
        snprintf(msg, msg_size, "out of memory for the WCSPH scheme of %d particles", p->n);
        return NULL;
    }
    return s;
}

void fluid_scheme_free(fluid_scheme *s)
{
    if (!s)
        return;
    fluid_verlet_free(&s->list);
    fluid_rows_free(&s->rows);
    wcsph_scratch_free(&s->scratch);
    fluid_wc_integrator_free(&s->predictor_corrector);
    fluid_wc_verlet_free(&s->verlet_integrator);
    free(s->velocity_for_viscosity);
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

static wcsph_neighbours neighbours(const fluid_scheme *s)
{
    return (wcsph_neighbours){&s->list, &s->rows, &s->kernel};
}

int fluid_scheme_rates(fluid_scheme *s, fluid_particles *p, double *drho_dt, double *dv_dt,
                       char *msg, size_t msg_size)
{
    if (reserve(s, p->n) != 0) {
        snprintf(msg, msg_size, "out of memory for the WCSPH scheme of %d particles", p->n);
        return -1;
    }
    fluid_phase_start(&s->phases, PHASE_STATE);
    /* 004 Eq. 4 both ways: a weakly compressible liquid under tension near a free
     * surface. */
    tait_eos_update_fluid(&s->eos, p, 1);
    fluid_phase_stop(&s->phases, PHASE_STATE);
    fluid_phase_start(&s->phases, PHASE_SEARCH);
    const int built = fluid_verlet_update(&s->list, p, s->kernel.support, s->skin);
    fluid_phase_stop(&s->phases, PHASE_SEARCH);
    fluid_phase_start(&s->phases, PHASE_ROWS);
    const int rc = built < 0                     ? -1
                   : built > 0 || s->rows_stale ? fluid_rows_build(&s->rows, &s->list, p, 0)
                                                 : 0;
    if (rc != 0) {
        fluid_phase_stop(&s->phases, PHASE_ROWS);
        snprintf(msg, msg_size, "cannot build the neighbour lists of %d particles (a "
                 "position is not finite, or memory ran out)", p->n);
        return -1;
    }
    s->rows_stale = 0;
    wcsph_pairs(&s->rows, &s->kernel,
                fsi_periodic_any(&s->list.periodic) ? &s->list.periodic : NULL, p);
    fluid_phase_stop(&s->phases, PHASE_ROWS);
    const wcsph_neighbours nb = neighbours(s);
    fluid_phase_start(&s->phases, PHASE_WALLS);
    wcsph_walls(&nb, &s->eos, s->prm.gravity, s->free_slip, p, s->velocity_for_viscosity);
    fluid_phase_stop(&s->phases, PHASE_WALLS);
    fluid_phase_start(&s->phases, PHASE_GRADIENTS);
    wcsph_gradients(&nb, &s->prm, p, s->velocity_for_viscosity, &s->scratch);
    fluid_phase_stop(&s->phases, PHASE_GRADIENTS);
    fluid_phase_start(&s->phases, PHASE_MOMENTUM);
    wcsph_rates(&nb, &s->prm, p, s->velocity_for_viscosity, &s->scratch, drho_dt, dv_dt);
    fluid_phase_stop(&s->phases, PHASE_MOMENTUM);
    return 0;
}

int fluid_scheme_step(fluid_scheme *s, fluid_particles *p, double t, double dt,
                      const fluid_step_hooks *hooks, char *msg, size_t msg_size)
{
    if (s->verlet)
        return fluid_wc_verlet_step(&s->verlet_integrator, p, t, dt, hooks, msg, msg_size);
    return fluid_wc_step(&s->predictor_corrector, p, t, dt, hooks, msg, msg_size);
}

void fluid_scheme_after_step(fluid_scheme *s, fluid_particles *p, long count)
{
    (void)s;
    (void)p;
    (void)count; /* delta-SPH diffuses the density in every evaluation: no filter */
}

double fluid_scheme_stable_dt(const fluid_scheme *s, const fluid_particles *p, double amax)
{
    return fluid_stable_step(&s->step, fluid_largest_speed(p), amax);
}

void fluid_scheme_pressure_gradient(const fluid_scheme *s, const fluid_particles *p,
                                    double *grad)
{
    const wcsph_neighbours nb = neighbours(s);
    wcsph_gradient(&nb, &s->prm, p, p->pressure, grad);
}

void fluid_scheme_boundary_loads(const fluid_scheme *s, const fluid_particles *p,
                                 double *force)
{
    const wcsph_neighbours nb = neighbours(s);
    wcsph_boundary_loads(&nb, &s->prm, p, s->velocity_for_viscosity, &s->scratch, force);
}

int fluid_scheme_write_fields(const fluid_scheme *s, fsi_h5_writer *out)
{
    (void)s;
    (void)out; /* no fields of its own */
    return 0;
}

int fluid_scheme_describe_fields(fsi_h5_writer *out)
{
    (void)out;
    return 0;
}

/* State between steps: the candidate lists (the rows are derived from them again, as
 * after a build) and the Verlet integrator's previous state; the predictor-corrector
 * keeps none, and delta-SPH has no filter. */
int fluid_scheme_save_state(const fluid_scheme *s, const fluid_particles *p, fsi_state *st)
{
    if (fluid_verlet_save(&s->list, st, "wcsph.list") != 0 ||
        fluid_wc_verlet_save(&s->verlet_integrator, p->n, st, "wcsph.verlet") != 0)
        return -1;
    return st->failed ? -1 : 0;
}

int fluid_scheme_restore_state(fluid_scheme *s, fluid_particles *p, const fsi_state *st)
{
    (void)p;
    if (fluid_verlet_restore(&s->list, st, "wcsph.list") != 0 ||
        fluid_wc_verlet_restore(&s->verlet_integrator, st, "wcsph.verlet") != 0)
        return -1;
    s->rows_stale = 1;
    return 0;
}

long long fluid_scheme_pair_count(const fluid_scheme *s)
{
    return s->scratch.pairs;
}
