/* Keys every fluid scheme has and the fluid's object sections (docs/cases.md is
 * generated from these tables: each description is one sentence a user reads). */
#include "fluid_keys.h"

#include "dim.h"
#include "shape.h"

#if FSI_DIM == 2
#define ZERO_VECTOR "0, 0"
#define UNIT_X "1, 0"
#define PERIODIC_AXES "none|x|y|xy"
#else
#define ZERO_VECTOR "0, 0, 0"
#define UNIT_X "1, 0, 0"
#define PERIODIC_AXES "none|x|y|z|xy|xz|yz|xyz"
#endif

static const fsi_key_spec common_keys[] = {
    {"spacing", FSI_KEY_REAL, "m", NULL, FSI_BOUND_MIN_OPEN, 0, 0, NULL,
     "Initial particle spacing dx: blocks and walls are filled with particles at "
     "min + (i + 1/2) dx, each of volume dx^DIM, so every box must be a whole number of "
     "spacings long."},
    /* Ranges of physics, not of the machine (the step they give is checked apart,
     * fluid_check.c): from thin gases (air at 30 km: 0.02 kg/m^3) to four times the
     * densest element (osmium, 22590 kg/m^3); up to ten million times water's viscosity,
     * beyond molasses and honey (10-100 Pa s): stiffer pastes and melts are no weakly
     * compressible Newtonian liquid. */
    {"density", FSI_KEY_REAL, "kg/m^3", "1000", FSI_BOUND_MIN | FSI_BOUND_MAX, 1e-3, 1e5, NULL,
     "Reference density rho0 of the fluid (000 Eq. 6)."},
    {"viscosity", FSI_KEY_REAL, "Pa s", "1e-3", FSI_BOUND_MIN | FSI_BOUND_MAX, 0, 1e4, NULL,
     "Dynamic viscosity mu of the Newtonian viscous stress tau = 2 mu e' (000 Eqs. 4-5); "
     "the physical value (water: 1e-3)."},
    {"sound_speed", FSI_KEY_REAL, "m/s", "0", FSI_BOUND_MIN, 0, 0, NULL,
     "Reference sound speed c0 of the equation of state (000 Eq. 6); 0 derives it from "
     "000 Eq. 7, c0 = 10 max(sqrt(max_pressure / rho0), max_velocity)."},
    {"max_velocity", FSI_KEY_REAL, "m/s", "0", FSI_BOUND_MIN, 0, 0, NULL,
     "Largest velocity expected in the flow, U_max of 000 Eq. 7 (e.g. sqrt(2 g H) for "
     "water falling from a height H); used only when sound_speed = 0."},
    {"max_pressure", FSI_KEY_REAL, "Pa", "0", FSI_BOUND_MIN, 0, 0, NULL,
     "Largest pressure expected in the flow, p_max of 000 Eq. 7 (e.g. rho0 g H at the "
     "bottom of a column of depth H); used only when sound_speed = 0."},
    {"tait_exponent", FSI_KEY_REAL, "-", "7", FSI_BOUND_MIN, 1, 0, NULL,
     "Exponent gamma of the Tait equation of state p = rho0 c0^2 / gamma ((rho / "
     "rho0)^gamma - 1) (000 Eq. 6; 7 for water)."},
    {"gravity", FSI_KEY_VECTOR, "m/s^2", ZERO_VECTOR, 0, 0, 0, NULL,
     "Body acceleration g on every fluid particle (000 Eq. 2); coupled scenes give the "
     "solid the same vector."},
    {"initial_pressure", FSI_KEY_CHOICE, "-", "hydrostatic", 0, 0, 0, "hydrostatic|zero",
     "hydrostatic: each block starts with p = rho0 |g| depth below its top (the corner "
     "highest against gravity) and the density of that pressure, so a fluid at rest "
     "starts in equilibrium; zero: p = 0, rho = rho0 everywhere (an acoustic transient "
     "follows)."},
    {"cfl_acoustic", FSI_KEY_REAL, "-", "0.25", FSI_BOUND_MIN_OPEN | FSI_BOUND_MAX, 0, 1, NULL,
     "Acoustic limit of the step: dt <= cfl_acoustic h / (c0 + |v|max) (Monaghan 1992's "
     "0.25 for the predictor-corrector, h the smoothing length)."},
    {"cfl_viscous", FSI_KEY_REAL, "-", "0.125", FSI_BOUND_MIN_OPEN | FSI_BOUND_MAX, 0, 1, NULL,
     "Viscous limit of the step: dt <= cfl_viscous rho0 h^2 / mu (Morris et al. 1997's "
     "0.125)."},
    {"cfl_force", FSI_KEY_REAL, "-", "0.25", FSI_BOUND_MIN_OPEN | FSI_BOUND_MAX, 0, 1, NULL,
     "Force limit of the step: dt <= cfl_force sqrt(h / |a|max) (Monaghan 1992's 0.25)."},
    {"periodic", FSI_KEY_CHOICE, "-", "none", 0, 0, 0, PERIODIC_AXES,
     "Axes along which the fluid is periodic: a particle leaving the period box "
     "periodic_min .. periodic_max re-enters at the other end and pairs interact across "
     "the boundary through the nearest image; every block and wall must lie inside the "
     "box along those axes, whose length must be a whole number of spacings."},
    {"periodic_min", FSI_KEY_VECTOR, "m", ZERO_VECTOR, 0, 0, 0, NULL,
     "Lower corner of the period box (only the periodic axes' components are used)."},
    {"periodic_max", FSI_KEY_VECTOR, "m", ZERO_VECTOR, 0, 0, 0, NULL,
     "Upper corner of the period box; its length along a periodic axis must be at least "
     "three supports of the kernel."},
    {"solid_acceleration", FSI_KEY_BOOL, "-", "true", 0, 0, 0, NULL,
     "Coupled runs: whether the solid's acceleration a_S enters the pressure the fluid "
     "gives the solid's particles (000 Eq. 52, p_S = ... - rho0 (g - a_S) . r). false: "
     "only gravity, as for a fixed wall; for thin or light bodies, whose inner particles "
     "the fluid reaches, the a_S term feeds the solid's own acceleration back into its load "
     "one window late (an added-mass loop, docs/coupling.md)."},
    {"reorder_interval", FSI_KEY_INT, "-", "200", FSI_BOUND_MIN, 0, 0, NULL,
     "Every this many steps (at the next window's start) the fluid and wall particles are "
     "sorted by cell so that neighbours sit close in memory (a speed matter only: the "
     "output keeps the particles in their original order); 0 never."},
    {"energy_growth_limit", FSI_KEY_REAL, "-", "2", FSI_BOUND_MIN_OPEN, 1, 0, NULL,
     "The run stops as unstable when the kinetic energy exceeds this factor times (the "
     "initial kinetic and compression energy + the potential energy released since the "
     "start) plus a floor of 1e-6 M c0^2; a stable fluid stays at or below 1 of it."},
};

const fsi_key_table fsi_fluid_common_keys = {
    "fluid_common",
    "Keys every fluid scheme has: the lattice, the fluid's properties and equation of "
    "state, gravity, the time-step limits and the energy check of the fluid main loop "
    "(fluid_solver/README.md).",
    common_keys, (int)(sizeof common_keys / sizeof common_keys[0])};

static const fsi_key_spec block_keys[] = {
    {"min", FSI_KEY_VECTOR, "m", "", 0, 0, 0, NULL,
     "Lower corner of the box of water filled with particles (shape = box: required)."},
    {"max", FSI_KEY_VECTOR, "m", "", 0, 0, 0, NULL,
     "Upper corner; max - min must be a whole number of spacings along each axis, at "
     "least one (shape = box: required)."},
    FSI_SHAPE_KEYS("The shape is filled with water; with initial_pressure = hydrostatic "
                   "the depth is counted from its highest point."),
};

const fsi_key_table fsi_fluid_block_keys = {
    "fluid.block", "A box of fluid filled with a regular lattice of particles.", block_keys,
    (int)(sizeof block_keys / sizeof block_keys[0])};

static const fsi_key_spec wall_keys[] = {
    {"min", FSI_KEY_VECTOR, "m", "", 0, 0, 0, NULL,
     "Lower corner of the box of fixed wall (ghost) particles (000 §2.3); make walls 3 to "
     "4 spacings thick so that the fluid near them has a full support (shape = box: "
     "required)."},
    {"max", FSI_KEY_VECTOR, "m", "", 0, 0, 0, NULL,
     "Upper corner; max - min must be a whole number of spacings along each axis (shape = "
     "box: required)."},
    FSI_SHAPE_KEYS("The wall is the shape filled with wall particles, as a box wall is: "
                   "give it 3 to 4 spacings of thickness wherever fluid meets it (a turned "
                   "box's smaller side, an annulus's radius - inner_radius; a disc or "
                   "polygon is filled whole, an obstacle). The leak check follows only "
                   "axis-aligned box walls."),
    {"free_slip", FSI_KEY_BOOL, "-", "false", 0, 0, 0, NULL,
     "false: no-slip, the wall's particles carry the virtual velocity 2 v_wall - v~ of "
     "000 Eqs. 50-51 into the viscous stress; true: free-slip, they carry v~ (no viscous "
     "shear from the wall)."},
    {"motion", FSI_KEY_CHOICE, "-", "none", 0, 0, 0, "none|harmonic",
     "none: the wall is fixed; harmonic: it translates rigidly by X(t) = motion_amplitude "
     "(sin(2 pi t / motion_period + motion_phase) - sin(motion_phase)) along "
     "motion_direction, counted from where it is drawn, and its pressure uses its "
     "acceleration X'' (000 Eq. 52); give several walls the same motion to move a tank."},
    {"motion_amplitude", FSI_KEY_REAL, "m", "0", 0, 0, 0, NULL,
     "Amplitude A of the harmonic motion (000 Eq. 60's A0)."},
    {"motion_period", FSI_KEY_REAL, "s", "1", FSI_BOUND_MIN_OPEN, 0, 0, NULL,
     "Period T of the harmonic motion."},
    {"motion_phase", FSI_KEY_REAL, "deg", "0", 0, 0, 0, NULL,
     "Phase of the harmonic motion in degrees; 90 gives the velocity -(2 pi A / T) "
     "sin(2 pi t / T) of the sloshing tank (000 Eq. 60), starting at rest."},
    {"motion_direction", FSI_KEY_VECTOR, "-", UNIT_X, 0, 0, 0, NULL,
     "Direction of the harmonic motion (normalised; must not be zero)."},
};

const fsi_key_table fsi_fluid_wall_keys = {
    "fluid.wall",
    "A box of wall particles, fixed or moving with a prescribed motion, whose pressure and density are extrapolated from the "
    "fluid (000 Eqs. 50-54).",
    wall_keys, (int)(sizeof wall_keys / sizeof wall_keys[0])};

static const fsi_key_spec probe_keys[] = {
    {"point", FSI_KEY_VECTOR, "m", NULL, 0, 0, 0, NULL,
     "Where the pressure is measured: the nearest fluid particle's pressure carried to "
     "the point with its pressure gradient (000 Eq. 13), column NAME_p of probes.csv; the "
     "point must lie in (or on the edge of) a block."},
    {"quantity", FSI_KEY_CHOICE, "-", "pressure", 0, 0, 0, "pressure|elevation",
     "pressure: column NAME_p as described at point; elevation: column NAME_eta, the "
     "height of the free surface above the point, i.e. the largest vertical coordinate of "
     "the fluid particles within one spacing horizontally of the point plus half a "
     "spacing (the surface lies half a spacing above the top particle's centre), minus "
     "the point's (put the point on the still surface to get the elevation)."},
    {"follow", FSI_KEY_STRING, "-", "", 0, 0, 0, NULL,
     "Name of a [fluid.wall] whose prescribed motion the point follows (a probe fixed to "
     "a moving tank); without it the point is fixed."},
};

const fsi_key_table fsi_fluid_probe_keys = {
    "fluid.probe",
    "The fluid pressure or the free-surface elevation at a point, recorded in probes.csv.", probe_keys,
    (int)(sizeof probe_keys / sizeof probe_keys[0])};

const fsi_object_kind fsi_fluid_object_kinds[FSI_FLUID_N_OBJECT_KINDS] = {
    {"block", "Boxes (or turned boxes, discs, polygons) of fluid at the start.", &fsi_fluid_block_keys, 1},
    {"wall", "Boxes (or turned boxes, discs, polygons) of fixed wall particles (a tank is several).", &fsi_fluid_wall_keys, 0},
    {"probe", "Points where the pressure or the surface elevation goes to probes.csv.",
     &fsi_fluid_probe_keys, 0},
};
