/* Keys every solid model has and the solid's object sections (docs/cases.md is
 * generated from these tables: each description is one sentence a user reads). */
#include "solid_keys.h"

#include "dim.h"
#include "shape.h"

#if FSI_DIM == 2
#define ZERO_VECTOR "0, 0"
#else
#define ZERO_VECTOR "0, 0, 0"
#endif

static const fsi_key_spec common_keys[] = {
    {"spacing", FSI_KEY_REAL, "m", NULL, FSI_BOUND_MIN_OPEN, 0, 0, NULL,
     "Lattice spacing dx: blocks are filled with points at min + (i + 1/2) dx, each of "
     "volume dx^DIM, so every block must be a whole number of spacings long."},
    /* Above 1 is allowed (with a warning at start-up) so that a user, or a test, can
     * drive the integration past the estimated stable step and see the run stop with
     * a message instead of writing NaN; 4 is where every model measured so far is
     * unstable (docs/nosbpd.md, Stable step), so larger values test nothing more. */
    {"time_step_safety", FSI_KEY_REAL, "-", "0.8", FSI_BOUND_MIN_OPEN | FSI_BOUND_MAX, 0,
     SOLID_TIME_STEP_SAFETY_MAX, NULL,
     "Fraction of the model's stable step used as the integrator's sub-step; each "
     "coupling window is split into ceil(window / (time_step_safety * stable step)) equal "
     "sub-steps. Values above 1 (up to 4) go beyond the estimated stable step: the run "
     "warns at start-up and may stop as unstable."},
    {"integrator", FSI_KEY_CHOICE, "-", "verlet", 0, 0, 0, "verlet|rk4",
     "Time integrator of the sub-steps: verlet (velocity Verlet, 000 Eq. 55, one force "
     "evaluation a step) or rk4 (classical fourth-order Runge-Kutta, 003 Eqs. 43-45, four); "
     "rk4 only with a model whose force depends on the positions alone (tlsph), since its "
     "trial stages would corrupt the committed state of nosbpd and pseudo_spring."},
    {"damping", FSI_KEY_REAL, "1/s", "0", FSI_BOUND_MIN, 0, 0, NULL,
     "Mass-proportional damping c: every point feels -c v per unit mass (treated implicitly, "
     "so any value is stable); use it to reach a static state, leave it 0 for dynamics."},
    {"gravity", FSI_KEY_VECTOR, "m/s^2", ZERO_VECTOR, 0, 0, 0, NULL,
     "Body acceleration on every point of the solid; solid-only scenes choose, coupled "
     "scenes give the same vector as the fluid."},
    {"initial_velocity", FSI_KEY_CHOICE, "-", "none", 0, 0, 0, "none|cantilever_mode",
     "Initial velocity field: none (at rest) or cantilever_mode, the first bending mode "
     "vy(x) = mode_amplitude c0 f(x) / f(L), kL = 1.875, of Gray et al. 2001 "
     "(benchmarks S2), with c0 = sqrt(K / rho) from the material's bulk modulus K."},
    {"mode_amplitude", FSI_KEY_REAL, "-", "0.01", FSI_BOUND_NONE, 0, 0, NULL,
     "V0L of the cantilever mode: the free end's initial transverse velocity divided by "
     "c0 = sqrt(K / rho)."},
    {"mode_length", FSI_KEY_REAL, "m", "0", FSI_BOUND_MIN, 0, 0, NULL,
     "L of the cantilever mode: the length from the clamp to the free end along x "
     "(required, > 0, with initial_velocity = cantilever_mode)."},
    {"mode_origin", FSI_KEY_REAL, "m", "0", FSI_BOUND_NONE, 0, 0, NULL,
     "x of the clamped end for the cantilever mode; points with x below it start at rest."},
    /* 0 means derived (solid_interface_depth): a key, not a protocol field, because
     * the fluid's reach is a property of the case (its [fluid] spacing and the derived
     * [fluid] support) that the solid can read before the first window, and so can the
     * case check. */
    {"interface_depth", FSI_KEY_REAL, "m", "0", FSI_BOUND_MIN, 0, 0, NULL,
     "Depth below the body's surface (reference configuration) within which every point "
     "is sent to the fluid as a boundary particle, besides the points whose horizon a "
     "free surface or crack cuts; 0 derives it from the fluid's support radius (the "
     "derived [fluid] support) less half a fluid spacing, and a smaller value than that "
     "is refused; a fluid without a support (an example or external fluid) leaves only "
     "the horizon-cut points unless it is given (docs/coupling.md, Unequal spacings)."},
    {"interface_impedance", FSI_KEY_BOOL, "-", "true", 0, 0, 0, NULL,
     "Answer for the fluid inside a coupling window: the load is corrected by the fluid's "
     "impedance times the particle's departure from the motion the fluid was given "
     "(docs/coupling.md, The fluid's answer inside the window); false holds the fluid's load "
     "as received, the plain serial-staggered scheme (for stability maps: docs/stability.md)."},
    {"energy_growth_limit", FSI_KEY_REAL, "-", "2", FSI_BOUND_MIN_OPEN, 1, 0, NULL,
     "The run stops as unstable when kinetic plus strain energy exceeds this factor times "
     "(initial energy + the work the loads, gravity and fluid have put in); a stable run "
     "stays at or below 1 of it."},
};

const fsi_key_table fsi_solid_common_keys = {
    "solid_common",
    "Keys every solid model has: the lattice, time stepping, damping, body force, initial "
    "velocity and the energy check of the solid main loop (solid_solver/README.md).",
    common_keys, (int)(sizeof common_keys / sizeof common_keys[0])};

static const fsi_key_spec block_keys[] = {
    {"min", FSI_KEY_VECTOR, "m", "", 0, 0, 0, NULL,
     "Lower corner of the box the block fills with lattice points (shape = box: "
     "required)."},
    {"max", FSI_KEY_VECTOR, "m", "", 0, 0, 0, NULL,
     "Upper corner of the box; max - min must be a whole number of spacings along each "
     "axis, at least one (shape = box: required)."},
    FSI_SHAPE_KEYS("The shape is filled with material; regions (clamps, loads, removal) "
                   "select its points by their boxes as for any block, and a block of "
                   "another shape touching a box block joins it where their lattices meet "
                   "(the same lattice when the box's corners lie on multiples of the "
                   "spacing)."),
};

const fsi_key_table fsi_solid_block_keys = {
    "solid.block", "A box of solid material filled with a regular lattice.", block_keys,
    (int)(sizeof block_keys / sizeof block_keys[0])};

static const fsi_key_spec region_keys[] = {
    {"min", FSI_KEY_VECTOR, "m", NULL, 0, 0, 0, NULL,
     "Lower corner of the box; a point belongs to the region when it lies in the closed "
     "box (within 1e-6 spacings)."},
    {"max", FSI_KEY_VECTOR, "m", NULL, 0, 0, 0, NULL, "Upper corner of the box."},
    {"action", FSI_KEY_CHOICE, "-", NULL, 0, 0, 0, "clamp|load|remove|no_failure",
     "clamp: the points keep x = x0 and v = a = 0; load: the points share 'force'; remove: "
     "no points are created there (notches, holes), before the other regions select; "
     "no_failure: no bond with an end point in the box breaks (a zone next to a clamp "
     "whose corner is an idealised singularity, docs/nosbpd.md)."},
    {"force", FSI_KEY_VECTOR, "N", ZERO_VECTOR, 0, 0, 0, NULL,
     "Total force of a load region (per unit thickness in 2D), spread equally over its "
     "points; required with action = load."},
    {"ramp_time", FSI_KEY_REAL, "s", "0", FSI_BOUND_MIN, 0, 0, NULL,
     "A load grows linearly from 0 at t = 0 to 'force' at t = ramp_time and then holds; 0 "
     "applies it at once."},
    {"clamp_face", FSI_KEY_CHOICE, "-", "none", 0, 0, 0, "none|x_min|x_max|y_min|y_max|z_min|z_max",
     "Clamp only: the face of the box that the body touches. Each clamped point then "
     "mirrors the body point at its image across that face (displacement -u), so that "
     "the families near the clamp see a displacement field that vanishes on the face "
     "and continues smoothly; the clamped points are not material (no mass, no strain "
     "energy). This removes the softening by about one horizon that a fixed layer gives "
     "(docs/nosbpd.md, Clamps). none: the points stay at x0 and are material held by a "
     "rigid fixture. The box should be one horizon thick."},
};

const fsi_key_table fsi_solid_region_keys = {
    "solid.region", "A box that clamps, loads, removes or keeps from breaking the lattice points in it.",
    region_keys, (int)(sizeof region_keys / sizeof region_keys[0])};

static const fsi_key_spec probe_keys[] = {
    {"point", FSI_KEY_VECTOR, "m", NULL, 0, 0, 0, NULL,
     "Reference position; the probe follows the particle nearest to it (within one "
     "spacing) and writes the columns NAME_ux, NAME_uy (, NAME_uz), NAME_vx, NAME_vy "
     "(, NAME_vz) of probes.csv."},
};

const fsi_key_table fsi_solid_probe_keys = {
    "solid.probe", "Displacement and velocity of one particle, recorded in probes.csv.",
    probe_keys, (int)(sizeof probe_keys / sizeof probe_keys[0])};

static const fsi_key_spec crack_keys[] = {
    {"from", FSI_KEY_VECTOR, "m", NULL, 0, 0, 0, NULL,
     "One end of the crack, a straight segment in the reference configuration (2D builds "
     "only)."},
    {"to", FSI_KEY_VECTOR, "m", NULL, 0, 0, 0, NULL,
     "The other end; every bond whose reference segment crosses the crack is broken from "
     "the start, whether failure is on or not. Draw it between lattice rows (a point on "
     "the crack's line keeps its bonds to both sides)."},
};

const fsi_key_table fsi_solid_crack_keys = {
    "solid.crack", "A pre-existing crack: a segment that the bonds across it do not span.",
    crack_keys, (int)(sizeof crack_keys / sizeof crack_keys[0])};

const fsi_object_kind fsi_solid_object_kinds[FSI_SOLID_N_OBJECT_KINDS] = {
    {"block", "Boxes (or turned boxes, discs, polygons) of material; touching blocks form one body.", &fsi_solid_block_keys, 1},
    {"region", "Clamps, loads and removed parts (applied in file order after removal).",
     &fsi_solid_region_keys, 0},
    {"probe", "Particles whose displacement and velocity go to probes.csv.",
     &fsi_solid_probe_keys, 0},
    {"crack", "Pre-existing cracks (notches of zero width) of a bond-based model.",
     &fsi_solid_crack_keys, 0},
};

const int fsi_solid_n_object_kinds =
    (int)(sizeof fsi_solid_object_kinds / sizeof fsi_solid_object_kinds[0]);
