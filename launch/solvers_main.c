/* `fsi solvers`: the solvers a case may name, from the registry `fsi run` validates
 * against, one line each: role, name, kind (solver, or example for the example
 * participants of examples/), program and whether it is built next to this one.
 * The lines that do not start with '#' are for scripts too: whitespace-separated
 * fields, in that order (tests/system/test_solver_combinations.sh runs every fluid
 * solver with every solid solver from them). */
#include <limits.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "cli_args.h"
#include "log.h"
#include "run_plan.h"
#include "solver_registry.h"

static void usage(FILE *out)
{
    fprintf(out, "usage: fsi solvers\n"
                 "  the solvers a case may name: role, name, kind, program, built or not\n");
}

int main(int argc, char **argv)
{
    fsi_args a = fsi_args_begin(argc, argv, "fsi solvers", usage);
    while (fsi_args_next(&a))
        fsi_arg_unknown(&a);
    if (a.error)
        return FSI_EXIT_BAD_INPUT;
    const fsi_case_schema *schema = fsi_project_schema();
    char bin[PATH_MAX];
    fsi_bin_dir(bin, sizeof bin);
    int name_w = (int)strlen("solver"), program_w = (int)strlen("program");
    for (int i = 0; i < schema->n_solvers; i++) {
        const fsi_solver_spec *s = &schema->solvers[i];
        int n = (int)strlen(s->name), p = (int)strlen(s->executable);
        name_w = n > name_w ? n : name_w;
        program_w = p > program_w ? p : program_w;
    }
    printf("# the solvers a case may name (solver = NAME in [fluid] or [solid]; their keys: "
           "fsi keys)\n");
    printf("# %-5s %-*s %-7s %-*s %s\n", "role", name_w, "solver", "kind", program_w, "program",
           "built");
    for (int r = 0; r < schema->n_roles; r++)
        for (int i = 0; i < schema->n_solvers; i++) {
            const fsi_solver_spec *s = &schema->solvers[i];
            if (strcmp(s->role, schema->roles[r]) != 0)
                continue;
            char program[PATH_MAX + 64];
            snprintf(program, sizeof program, "%s/%s", bin, s->executable);
            printf("  %-5s %-*s %-7s %-*s %s\n", s->role, name_w, s->name,
                   s->example ? "example" : "solver", program_w, s->executable,
                   access(program, X_OK) == 0 ? "yes" : "no");
        }
    printf("# solver = external: a program of your own, executable = PATH "
           "(docs/participant_api.md)\n");
    return 0;
}
