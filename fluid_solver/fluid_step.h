/* The fluid's time step: the sound speed c0 of the case (000 Eq. 7 when derived) and
 * the acoustic, viscous and force limits every explicit weakly compressible scheme
 * obeys. One function for the running scheme (fluid_scheme_stable_dt) and for the case
 * check (fluid_check.c), which estimates the step before anything runs: the check's
 * estimate is the step of the fluid at rest, an upper bound of every later step (a
 * moving fluid only adds |v|max and |a|max), so a case it refuses would take at least
 * the number of steps it names. */
#ifndef FSI_FLUID_STEP_H
#define FSI_FLUID_STEP_H

#include "case_file.h"
#include "fluid_particles.h"

/* What the step limits need. */
typedef struct {
    double h;                   /* smoothing length [m] */
    double sound_speed;         /* c0 [m/s] */
    double density;             /* rho0 [kg/m^3] */
    double viscosity;           /* mu [Pa s] */
    double cfl_acoustic, cfl_viscous, cfl_force;
    const char *cfl_acoustic_section, *cfl_acoustic_key; /* where cfl_acoustic was read:
                                 * the scheme's acoustic_step_factor or [fluid]'s */
} fluid_step_limits;

/* c0 from [role] sound_speed, or 000 Eq. 7 when it is 0:
 * c0 = 10 max(sqrt(max_pressure / rho0), max_velocity), which keeps the density within
 * about 1 % of rho0; 0 when neither is given. */
double fluid_sound_speed(const fsi_case *c, const char *role, double rho0);

/* The keys of [role] that fluid_stable_step reads, h = smoothing_factor * spacing
 * (smoothing_factor of the chosen scheme's section, fsi_case_solver_section;
 * fluid_scheme_smoothing_length of the running scheme). */
void fluid_step_limits_read(fluid_step_limits *l, const fsi_case *c, const char *role);

/* Acoustic limit cfl_acoustic h / (c0 + vmax) (Monaghan 1992). */
double fluid_acoustic_step(const fluid_step_limits *l, double vmax);
/* Viscous limit cfl_viscous rho0 h^2 / mu (Morris et al. 1997); infinite when mu = 0. */
double fluid_viscous_step(const fluid_step_limits *l);
/* The stable step: the smallest of the acoustic, viscous and force limit
 * cfl_force sqrt(h / amax) (Monaghan 1992; none when amax = 0). */
double fluid_stable_step(const fluid_step_limits *l, double vmax, double amax);

/* The largest speed of a fluid particle of p (the vmax of the acoustic limit) [m/s]. */
double fluid_largest_speed(const fluid_particles *p);

#endif
