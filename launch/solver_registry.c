#include "solver_registry.h"

#include <string.h>

#include "example_keys.h"
#include "fluid_keys.h"
#include "isph_keys.h"
#include "material.h"
#include "nosbpd_keys.h"
#include "pseudo_spring_keys.h"
#include "run_keys.h"
#include "solid_keys.h"
#include "tlsph_keys.h"
#include "ulph_keys.h"
#include "wcsph_keys.h"

static const fsi_key_spec participant_keys[] = {
    {"solver", FSI_KEY_STRING, "-", NULL, 0, 0, 0, NULL,
     "Which solver plays this part (see the solver tables below), or 'external' for a "
     "program of your own that speaks the protocol (docs/participant_api.md)."},
    {"executable", FSI_KEY_STRING, "-", "", 0, 0, 0, NULL,
     "Program to start for solver = external (a path); ignored otherwise."},
    {"checkpoints", FSI_KEY_BOOL, "-", "false", 0, 0, 0, NULL,
     "For solver = external: the program saves and restores its state when the library "
     "asks (fsi_requires_writing_checkpoint, fsi_write_checkpoint, fsi_restart_state; "
     "docs/checkpoints.md), which [run] scheme = implicit and checkpoint_interval need; a "
     "case that needs it of a program that does not say so is refused. The project's "
     "solvers all do; ignored for them."},
    {"threads", FSI_KEY_INT, "-", "1", FSI_BOUND_MIN, 1, 0, NULL,
     "OpenMP threads of this participant (`fsi run --threads N` overrides it)."},
};

static const fsi_key_table participant_table = {
    "participant", "Keys every participant section has.", participant_keys,
    (int)(sizeof participant_keys / sizeof participant_keys[0])};

static const char *const roles[] = {"fluid", "solid"};

static const fsi_key_table *const spring_tables[] = {&fsi_spring_solid_keys};
static const fsi_key_table *const dashpot_tables[] = {&fsi_dashpot_fluid_keys};

/* In [solid] and [fluid]; each model's or scheme's own table goes in its solver
 * section ([solid.nosbpd], [fluid.ulph]). The examples' tables stay in [ROLE]: they
 * are the template for external programs, which read their keys there. */
static const fsi_key_table *const solid_model_tables[] = {&fsi_solid_common_keys,
                                                          &material_key_table};

static const fsi_key_table *const ulph_tables[] = {&fsi_fluid_common_keys};
static const fsi_key_table *const wcsph_tables[] = {&fsi_fluid_common_keys};
static const fsi_key_table *const isph_tables[] = {&fsi_fluid_common_keys};

#define N_TABLES(a) ((int)(sizeof(a) / sizeof((a)[0])))

/* Every solid model's semantic check: the geometry, the material's cross-key rules,
 * what the model accepts of the integrator and the constitutive laws, then the
 * sub-step they give (each writes one line per problem). */
static int solid_model_check(const fsi_case *c, const char *role, FILE *errors,
                             const solid_model_traits *traits)
{
    int n = solid_geometry_check(c, role, errors) + material_case_check(c, role, errors);
    n += solid_model_traits_check(c, role, traits, errors);
    return n + solid_step_check(c, role, errors);
}

static int nosbpd_check(const fsi_case *c, const char *role, FILE *errors)
{
    static const solid_model_traits t = {"nosbpd", 0, "bond failure and the stress update",
                                         1, 1};
    return solid_model_check(c, role, errors, &t);
}

static int pseudo_spring_check(const fsi_case *c, const char *role, FILE *errors)
{
    static const solid_model_traits t = {"pseudo_spring", 0,
                                         "link failure, density and the stress update", 1, 0};
    return solid_model_check(c, role, errors, &t);
}

static int tlsph_check(const fsi_case *c, const char *role, FILE *errors)
{
    static const solid_model_traits t = {"tlsph", 1, NULL, 0, 1};
    return solid_model_check(c, role, errors, &t);
}

static const fsi_solver_spec solvers[] = {
    {.name = "spring_oscillators", .role = "solid", .executable = "fsi-spring-solid",
     .description =
         "Example solid of independent mass-spring oscillators (examples/spring_solid.c).",
     .example = 1, .key_tables = spring_tables, .n_key_tables = N_TABLES(spring_tables)},
    {.name = "linear_dashpot", .role = "fluid", .executable = "fsi-dashpot-fluid",
     .description =
         "Example fluid: a linear dashpot on every solid particle (examples/dashpot_fluid.c).",
     .example = 1, .key_tables = dashpot_tables, .n_key_tables = N_TABLES(dashpot_tables)},
    {.name = "nosbpd", .role = "solid", .executable = "fsi-solid-nosbpd",
     .description =
         "Non-ordinary state-based peridynamics (correspondence model, Wang et al. 2024 "
         "(000) section 2.2) with zero-energy control, bond failure and Drucker-Prager "
         "plasticity (solid_solver/nosbpd, docs/nosbpd.md).",
     .key_tables = solid_model_tables, .n_key_tables = N_TABLES(solid_model_tables),
     .own_keys = &fsi_nosbpd_keys, .objects = fsi_solid_object_kinds,
     .n_objects = FSI_SOLID_N_OBJECT_KINDS, .check = nosbpd_check},
    {.name = "pseudo_spring", .role = "solid", .executable = "fsi-solid-pseudo-spring",
     .description =
         "Pseudo-spring SPH (Islam 2023 (004) section 3, Chakraborty & Shaw 2013): "
         "updated-Lagrangian SPH over the immediate lattice neighbours with the corrected "
         "kernel gradient, Jaumann stress rate, artificial viscosity and stress, and link "
         "failure (solid_solver/pseudo_spring, docs/pseudo_spring.md).",
     .key_tables = solid_model_tables, .n_key_tables = N_TABLES(solid_model_tables),
     .own_keys = &fsi_pseudo_spring_keys, .objects = fsi_solid_object_kinds,
     .n_objects = FSI_SOLID_N_OBJECT_KINDS, .check = pseudo_spring_check},
    {.name = "tlsph", .role = "solid", .executable = "fsi-solid-tlsph",
     .description =
         "Total-Lagrangian SPH (Salehizadeh & Shafiei 2022 (003) section 2.2, Lin et al. "
         "2015): reference-configuration kernel gradients with the shape-matrix correction, "
         "first Piola-Kirchhoff stress, linear elastic or hyperelastic materials, optional "
         "hourglass control, velocity Verlet or RK4 (solid_solver/tlsph, docs/tlsph.md).",
     .key_tables = solid_model_tables, .n_key_tables = N_TABLES(solid_model_tables),
     .own_keys = &fsi_tlsph_keys, .objects = fsi_solid_object_kinds,
     .n_objects = FSI_SOLID_N_OBJECT_KINDS, .check = tlsph_check},
    {.name = "ulph", .role = "fluid", .executable = "fsi-fluid-ulph",
     .description =
         "Updated Lagrangian Particle Hydrodynamics, a weakly compressible fluid with "
         "non-local operators, fixed ghost walls and predictor-corrector stepping (Wang et "
         "al. 2024 (000) section 2.1, fluid_solver/ulph, docs/ulph.md).",
     .key_tables = ulph_tables, .n_key_tables = N_TABLES(ulph_tables),
     .own_keys = &fsi_ulph_keys, .support = ulph_support, .objects = fsi_fluid_object_kinds,
     .n_objects = FSI_FLUID_N_OBJECT_KINDS, .check = fluid_geometry_check},
    {.name = "wcsph", .role = "fluid", .executable = "fsi-fluid-wcsph",
     .description =
         "Weakly compressible SPH with delta-SPH density diffusion, the Wendland C2 kernel, "
         "Adami dummy walls and a soft contact with the solid, predictor-corrector or "
         "Verlet stepping (Islam 2023 (004) section 2, fluid_solver/wcsph, docs/wcsph.md).",
     .key_tables = wcsph_tables, .n_key_tables = N_TABLES(wcsph_tables),
     .own_keys = &fsi_wcsph_keys, .support = wcsph_support, .objects = fsi_fluid_object_kinds,
     .n_objects = FSI_FLUID_N_OBJECT_KINDS, .check = fluid_geometry_check},
    {.name = "isph", .role = "fluid", .executable = "fsi-fluid-isph",
     .description =
         "Incompressible SPH: a projection with a pressure Poisson equation solved every step "
         "(BiCGSTAB with ILU(0)), free-surface detection, particle shifting, dummy walls and "
         "the solid as unknowns of the Poisson equation (Salehizadeh & Shafiei "
         "2022 (003) section 2.1, "
         "fluid_solver/isph, docs/isph.md).",
     .key_tables = isph_tables, .n_key_tables = N_TABLES(isph_tables),
     .own_keys = &fsi_isph_keys, .support = isph_support, .objects = fsi_fluid_object_kinds,
     .n_objects = FSI_FLUID_N_OBJECT_KINDS, .check = fluid_geometry_check},
};

static const fsi_case_schema schema = {
    &fsi_run_key_table, 1, &participant_table, roles, 2, solvers,
    (int)(sizeof solvers / sizeof solvers[0])};

const fsi_case_schema *fsi_project_schema(void)
{
    return &schema;
}

const fsi_solver_spec *fsi_find_solver(const char *name)
{
    for (size_t i = 0; i < sizeof solvers / sizeof solvers[0]; i++)
        if (strcmp(solvers[i].name, name) == 0)
            return &solvers[i];
    return NULL;
}
