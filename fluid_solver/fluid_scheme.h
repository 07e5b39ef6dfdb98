/* The functions every fluid scheme folder implements (ulph/, wcsph/, isph/), the
 * way SWIFT keeps each hydro scheme behind the same small set of functions. The main
 * loop (fluid_main.c) owns the particles, the choice of the step, the coupling, probes
 * and output; a scheme owns what it needs between steps (neighbour lists, operators,
 * scratch), computes rates and takes a step (weakly compressible schemes with the
 * shared predictor-corrector, integrators/wc_predictor_corrector.h; a projection
 * scheme its own). Shared physics lives beside the schemes: kernels/, eos/, walls/,
 * contact/, neighbours/.
 *
 * Contract per evaluation of the rates at the particles' current state:
 *   - fluid particles: the scheme sets pressure (equation of state) and volume
 *     (m / rho) from density, and returns drho/dt and dv/dt;
 *   - wall particles: the scheme sets their pressure, density and mass (the ghost
 *     boundary of 000 §2.3); their rates are zero: the main loop puts them where their
 *     prescribed motion says, with its velocity (v_S) and acceleration
 *     (p->boundary_acceleration, a_S), before each evaluation; moving boundary
 *     particles (the solid, fluid_boundary.h) likewise from the solid's state.
 * Rates of any other particle are zero. The number of particles may change between
 * calls (the moving boundary set at the tail, fluid_boundary.h): a scheme sizes its
 * per-particle scratch to p->n at every call. */
#ifndef FSI_FLUID_SCHEME_H
#define FSI_FLUID_SCHEME_H

#include <stddef.h>

#include "case_file.h"
#include "fluid_particles.h"
#include "h5_output.h"
#include "periodic.h"
#include "state_store.h"
#include "timers.h"

typedef struct fluid_scheme fluid_scheme;

/* What the main loop gives every scheme. */
typedef struct {
    double density;             /* rho0 [kg/m^3] */
    double viscosity;           /* mu [Pa s] */
    double sound_speed;         /* c0 [m/s], already derived (000 Eq. 7) */
    double tait_exponent;       /* gamma (000 Eq. 6) */
    double gravity[FSI_DIM];    /* [m/s^2] */
    const unsigned char *free_slip; /* per particle: 1 for a free-slip wall particle */
    fsi_periodic periodic;      /* periodic axes (fluid_periodic.h); none by default */
} fluid_properties;

/* Reads the scheme's keys from [role] and allocates its state for p. NULL with msg. */
fluid_scheme *fluid_scheme_create(const fsi_case *c, const char *role,
                                  const fluid_properties *props, const fluid_particles *p,
                                  char *msg, size_t msg_size);

/* 1 for a weakly compressible scheme (pressure from density by an equation of state, a
 * sound speed that bounds the step and the Mach number), 0 for a projection scheme
 * (pressure from a Poisson equation, density rho0: fluid_scheme_pressure is then 0 and
 * fluid_scheme_density rho0; no sound speed enters its step). */
int fluid_scheme_compressible(const fluid_scheme *s);

/* 1 when the main loop is to put fluid particles that a step took into a wall box back
 * on its face (fluid_leak_hold_and_check): a scheme whose forces do not hold every
 * particle out of the walls (ISPH's splash particles have no Poisson row). 0 for the
 * weakly compressible schemes, whose wall pressure does. */
int fluid_scheme_holds_at_walls(const fluid_scheme *s);

/* Pressure (and density) from the equation of state for every fluid particle. */
double fluid_scheme_pressure(const fluid_scheme *s, double density);
/* Density of a given pressure (the inverse, for initial conditions and walls). */
double fluid_scheme_density(const fluid_scheme *s, double pressure);

/* The energy a fluid particle of this density stores by its compression [J/kg]: the
 * pressure's work from rho0, int p / rho^2 drho, of the scheme's equation of state (a
 * diagnostic, fluid_diagnostics.h). 0 for a projection scheme, which stores none. */
double fluid_scheme_compression_energy(const fluid_scheme *s, double density);

/* Rates at the current state: drho_dt[n], dv_dt[n * FSI_DIM] (gravity included).
 * Returns 0, or -1 with msg (memory, a non-finite position). */
int fluid_scheme_rates(fluid_scheme *s, fluid_particles *p, double *drho_dt, double *dv_dt,
                       char *msg, size_t msg_size);

/* What the main loop lends a step. */
typedef struct {
    void *owner;
    /* Puts the walls and the moving boundary at time t and evaluates the rates at the
     * particles' current state into drho and accel below. 0, or -1 (the owner keeps
     * the message). */
    int (*evaluate)(void *owner, double t);
    /* Called once per step with the rates the step moves the particles with (the
     * predictor-corrector's at the midpoint, Verlet's at the start) in the last
     * evaluation: the loads on the solid and the moving walls' work over the step of
     * length dt. 0, or -1 (the owner's message). */
    int (*loads)(void *owner, double dt);
    double *drho, *accel;       /* the rates of the last evaluation, n and n * FSI_DIM */
    fsi_timers *timers;         /* the integration's own time goes to integrate_timer */
    int integrate_timer;
} fluid_step_hooks;

/* One step of length dt from time t, the rates at the current state already in
 * hooks->drho, hooks->accel: fluid particles move, wall particles do not (the hooks'
 * evaluate places them). Returns 0, or -1 with msg (or the owner's message, when a
 * hook failed). */
int fluid_scheme_step(fluid_scheme *s, fluid_particles *p, double t, double dt,
                      const fluid_step_hooks *hooks, char *msg, size_t msg_size);

/* Called by the main loop after each completed step (count = steps so far): e.g. the
 * density filter. Uses the neighbour lists of the last rates call. */
void fluid_scheme_after_step(fluid_scheme *s, fluid_particles *p, long count);

/* Largest stable step for the last rates (acoustic, viscous, force limits), with the
 * largest acceleration of a fluid particle amax. */
double fluid_scheme_stable_dt(const fluid_scheme *s, const fluid_particles *p, double amax);

/* Smoothing length h [m] (probes and messages). */
double fluid_scheme_smoothing_length(const fluid_scheme *s);
/* Support radius [m]: how far a particle's neighbours reach (the leak check's
 * tolerance). */
double fluid_scheme_support(const fluid_scheme *s);

/* Gradient of the pressure (000 Eq. 13) of every particle from the last rates call,
 * grad[n * FSI_DIM]. */
void fluid_scheme_pressure_gradient(const fluid_scheme *s, const fluid_particles *p,
                                    double *grad);

/* The force the fluid exerts on every moving boundary particle (force[n * FSI_DIM];
 * zero for the others) at the state of the last rates call: the exact reaction of the
 * pair terms between each boundary particle and its fluid neighbours, so that the
 * forces on fluid and boundary balance to round-off. */
void fluid_scheme_boundary_loads(const fluid_scheme *s, const fluid_particles *p,
                                 double *force);

/* The scheme's own fields of the current frame (e.g. flags of singular families). */
int fluid_scheme_write_fields(const fluid_scheme *s, fsi_h5_writer *out);
/* Their units, descriptions and flag names (fsi_h5_describe), before the first frame. */
int fluid_scheme_describe_fields(fsi_h5_writer *out);

/* From now on the scheme adds the wall time of its own phases (neighbour search,
 * operators, ...: names of its choosing) to t, so that the run log splits the main
 * loop's "rates" phase; t must outlive the scheme. NULL stops it. */
void fluid_scheme_use_timers(fluid_scheme *s, fsi_timers *t);

/* The main loop permuted the first n particles (fluid_main.c, order for locality): the
 * particle now at k was at sorted[k]. State the scheme keeps by particle index between
 * calls follows: candidate neighbour lists are rebuilt, an integrator's previous state
 * is permuted the same way (so that sorting changes only the order of sums). scratch
 * holds n * FSI_DIM doubles. */
void fluid_scheme_particles_reordered(fluid_scheme *s, const int *sorted, int n, void *scratch);

/* The scheme's state between steps, for implicit coupling (docs/coupling.md): the main
 * loop saves it with the particles at the start of a coupling window and restores both
 * when the coupler repeats the window (fluid_main.c, save_state). The state is
 * complete: from a restore, the same steps with the same solid reproduce the first
 * attempt bit for bit, on any number of threads (positions, velocities, densities,
 * pressures, loads). It is everything kept between calls that changes a later result:
 * an integrator's previous state, a filter that is due, a projection's last pressure
 * and what it was solved for, the candidate neighbour lists (a list rebuilt at another
 * step holds the same pairs in another order, which changes the sums' last bits), the
 * statistics the log reports; not scratch that every call writes before it reads it.
 * Entries are named "<scheme>.<what>" (core/state_store.h); save clears nothing, so
 * the main loop's own entries share st. save: 0, or -1 when memory runs out. restore:
 * p holds the particles saved with the state (the same p->n); 0, or -1 when st lacks
 * an entry or one has another size (a state of another scheme or case), or memory
 * runs out. */
int fluid_scheme_save_state(const fluid_scheme *s, const fluid_particles *p, fsi_state *st);
int fluid_scheme_restore_state(fluid_scheme *s, fluid_particles *p, const fsi_state *st);

/* Pairs per particle of the last neighbour list (for the performance line). */
long long fluid_scheme_pair_count(const fluid_scheme *s);

void fluid_scheme_free(fluid_scheme *s);

#endif
