#include "example_keys.h"

static const fsi_key_spec spring_keys[] = {
    {"particles", FSI_KEY_INT, "-", "100", FSI_BOUND_MIN, 1, 0, NULL,
     "Number of interface particles, each a mass on its own spring."},
    {"mass", FSI_KEY_REAL, "kg", "1", FSI_BOUND_MIN_OPEN, 0, 0, NULL, "Mass of each particle."},
    {"stiffness", FSI_KEY_REAL, "N/m", "100", FSI_BOUND_MIN_OPEN, 0, 0, NULL,
     "Spring stiffness of particle 0."},
    {"stiffness_spread", FSI_KEY_REAL, "-", "0.5", FSI_BOUND_MIN, 0, 0, NULL,
     "Particle i has stiffness * (1 + stiffness_spread * i / (particles - 1)), so that every "
     "particle carries different data."},
    {"initial_displacement", FSI_KEY_REAL, "m", "0.01", FSI_BOUND_NONE, 0, 0, NULL,
     "Initial displacement of every particle along y; they start at rest."},
    {"spacing", FSI_KEY_REAL, "m", "0.01", FSI_BOUND_MIN_OPEN, 0, 0, NULL,
     "Distance between neighbouring particles along x (they do not interact)."},
    {"time_step", FSI_KEY_REAL, "s", "1e-4", FSI_BOUND_MIN_OPEN, 0, 0, NULL,
     "Largest velocity-Verlet sub-step; the solid sub-cycles inside each coupling window."},
};

const fsi_key_table fsi_spring_solid_keys = {
    "spring_oscillators",
    "Example solid: independent mass-spring oscillators. With the linear_dashpot fluid each "
    "particle is a damped oscillator with a closed-form solution.",
    spring_keys, (int)(sizeof spring_keys / sizeof spring_keys[0])};

static const fsi_key_spec dashpot_keys[] = {
    {"damping", FSI_KEY_REAL, "N s/m", "2", FSI_BOUND_MIN, 0, 0, NULL,
     "Load -damping * v_y on each solid particle."},
    {"stiffness", FSI_KEY_REAL, "N/m", "0", FSI_BOUND_MIN, 0, 0, NULL,
     "Extra load -stiffness * u_y on each solid particle."},
    {"time_step", FSI_KEY_REAL, "s", "1e-3", FSI_BOUND_MIN_OPEN, 0, 0, NULL,
     "The window this fluid proposes to the coupler."},
};

const fsi_key_table fsi_dashpot_fluid_keys = {
    "linear_dashpot",
    "Example fluid: a linear dashpot (and optional spring) acting on every solid particle, "
    "evaluated from the solid state at the start of the window.",
    dashpot_keys, (int)(sizeof dashpot_keys / sizeof dashpot_keys[0])};
